#pragma once

#include <optional>

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "core/surface/textured_surface.hpp"
#include "gl/objects.hpp"

namespace morphogen::gl {

// Where the camera is and what the picture looks like.
struct ViewOptions {
    int width = 800; // the image, in pixels
    int height = 600;
    // The camera looks at the bounding sphere's centre from this direction:
    // azimuth round the +y axis (0: from +z, 90: from +x), elevation above
    // the xz plane, in degrees.
    double azimuth = 30;
    double elevation = 20;
    // From the centre, in bounding-sphere radii; 0 frames the model (the
    // sphere just fits the narrower field of view, with a small margin).
    double distance = 0;
    double fieldOfView = 30; // vertical, degrees
    // Each pixel is the mean of supersample^2 samples: smooth silhouettes and
    // texture detail on any GL (multisampling is not required).
    int supersample = 3;
    // RGBA; the alpha is what uncovered pixels get (0: a cut-out image).
    std::array<float, 4> background = {1.0f, 1.0f, 1.0f, 1.0f};
    // Towards the directional light, in camera space (x right, y up, z back
    // towards the viewer), so every turntable frame is lit alike.
    std::array<float, 3> light = {-0.45f, 0.6f, 0.66f};
};

// RGBA8 pixels, row 0 at the top (as image files store them).
struct SurfaceImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;
};

// Draws a TexturedMesh offscreen: depth-tested triangles, base colour and
// tangent-space normal map sampled bilinearly (no mipmaps: minification is
// handled by the supersampling, and no mip level can mix tiles), Lambert plus
// a little Blinn-Phong from one directional light, both faces lit (open
// surfaces); where a mesh has a metallic-roughness texture, its smooth
// texels shade as water (glsl/surface.frag). Needs a current context for its
// whole life (EGL or OSMesa); the mesh is uploaded once, then any number of
// views.
class SurfaceRenderer {
public:
    // Throws std::invalid_argument for a mesh whose attribute counts or
    // texture sizes do not agree.
    explicit SurfaceRenderer(const TexturedMesh& mesh);
    // Throws InputError for a size of 0 or one past GL's limits (naming it).
    SurfaceImage render(const ViewOptions& view) const;
    // New base colour and normal map for the same geometry (a pattern that
    // grows: the designer's live 3D view), without re-uploading the mesh or
    // re-building the program. Throws std::invalid_argument as the constructor.
    void setTextures(const TexturedMesh& mesh);

    const BoundingSphere& bounds() const { return m_bounds; }

private:
    void setMetallicRoughness(const TexturedMesh& mesh);

    Program m_program;
    VertexArray m_vao;
    Buffer m_vertices, m_indices;
    Texture2D m_baseColour, m_normalMap;
    Texture2D m_metallicRoughness; // 1 x 1 when the mesh has none (m_wet false)
    bool m_wet = false;
    std::size_t m_indexCount = 0;
    BoundingSphere m_bounds;
};

// The point of `mesh` seen at pixel (x, y) of `view` (continuous pixel
// coordinates, row 0 at the top) by the camera SurfaceRenderer uses for a
// model in `bounds`: the nearest triangle the ray through the pixel hits;
// none when it misses. Brute force over the triangles (interactive picking:
// one ray per mouse event).
std::optional<Eigen::Vector3f> pickSurface(const TriangleMesh& mesh, const BoundingSphere& bounds,
                                           const ViewOptions& view, double x, double y);

// One view of a tiled surface: texturedSurface, then SurfaceRenderer.
SurfaceImage renderSurface(const SurfaceTiles& tiles, const std::vector<float>& height,
                           const std::vector<std::array<std::uint8_t, 4>>& colours,
                           const ViewOptions& view, const SurfaceLook& look = {});

// `frames` views round the model: frame k at azimuth view.azimuth + 360 k / frames.
std::vector<SurfaceImage> renderTurntable(const SurfaceRenderer& renderer, const ViewOptions& view,
                                          int frames);

} // namespace morphogen::gl
