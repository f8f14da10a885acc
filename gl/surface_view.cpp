#include "gl/surface_view.hpp"

#include <limits>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Geometry>

#include "core/base/errors.hpp"

namespace morphogen::gl {

namespace {

constexpr int kBaseColourUnit = 0;
constexpr int kNormalMapUnit = 1;
constexpr int kMetallicRoughnessUnit = 2;
constexpr int kFloatsPerVertex = 12; // position 3, normal 3, uv 2, tangent 4
constexpr int kMaxSide = 16384;
constexpr double kPi = 3.14159265358979323846;

struct RenderbufferTraits {
    static void destroy(GLuint id) { glDeleteRenderbuffers(1, &id); }
};

double radians(double degrees) {
    return degrees * kPi / 180.0;
}

Texture2D uploadImage(const RgbaImage& image, const char* what) {
    if (image.width < 1 || image.height < 1 ||
        image.texels.size() != std::size_t(image.width) * std::size_t(image.height))
        throw std::invalid_argument(std::string("SurfaceRenderer: the ") + what + " is " +
                                    std::to_string(image.width) + " x " +
                                    std::to_string(image.height) + " with " +
                                    std::to_string(image.texels.size()) + " texels");
    Texture2D texture(image.width, image.height, GL_RGBA8);
    glBindTexture(GL_TEXTURE_2D, texture.id());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE,
                    image.texels.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    texture.setWrap(GL_CLAMP_TO_EDGE);
    return texture;
}

// The camera: world to clip space, and the frame the light is given in.
struct Camera {
    Eigen::Matrix4f viewProjection;
    Eigen::Vector3f eye, light;
};

Camera cameraFor(const BoundingSphere& bounds, const ViewOptions& view) {
    const double radius = bounds.radius > 0 ? bounds.radius : 1.0;
    const double aspect = double(view.width) / double(view.height);
    const double fovY = radians(view.fieldOfView);
    const double fovX = 2.0 * std::atan(aspect * std::tan(fovY / 2.0));
    const double fit = 1.12 / std::sin(std::min(fovX, fovY) / 2.0); // a margin round the model
    const double distance = (view.distance > 0 ? view.distance : fit) * radius;

    const double az = radians(view.azimuth), el = radians(view.elevation);
    const Eigen::Vector3f back(float(std::cos(el) * std::sin(az)), float(std::sin(el)),
                               float(std::cos(el) * std::cos(az)));
    Eigen::Vector3f right = Eigen::Vector3f::UnitY().cross(back);
    if (right.squaredNorm() < 1e-8f) // looking straight down or up
        right = Eigen::Vector3f::UnitX();
    right.normalize();
    const Eigen::Vector3f up = back.cross(right);

    Camera camera;
    camera.eye = bounds.centre + back * float(distance);
    Eigen::Matrix4f viewMatrix = Eigen::Matrix4f::Identity();
    viewMatrix.block<1, 3>(0, 0) = right.transpose();
    viewMatrix.block<1, 3>(1, 0) = up.transpose();
    viewMatrix.block<1, 3>(2, 0) = back.transpose();
    viewMatrix.block<3, 1>(0, 3) = -viewMatrix.block<3, 3>(0, 0) * camera.eye;

    const double farPlane = distance + radius * 1.05;
    const double nearPlane = std::max(distance - radius * 1.05, farPlane * 1e-3);
    const double f = 1.0 / std::tan(fovY / 2.0);
    Eigen::Matrix4f projection = Eigen::Matrix4f::Zero();
    projection(0, 0) = float(f / aspect);
    projection(1, 1) = float(f);
    projection(2, 2) = float((farPlane + nearPlane) / (nearPlane - farPlane));
    projection(2, 3) = float(2.0 * farPlane * nearPlane / (nearPlane - farPlane));
    projection(3, 2) = -1.0f;
    camera.viewProjection = projection * viewMatrix;

    const Eigen::Vector3f light(view.light[0], view.light[1], view.light[2]);
    camera.light = (right * light.x() + up * light.y() + back * light.z()).normalized();
    return camera;
}

} // namespace

std::optional<Eigen::Vector3f> pickSurface(const TriangleMesh& mesh, const BoundingSphere& bounds,
                                           const ViewOptions& view, double x, double y) {
    const Eigen::Matrix4f inverse = cameraFor(bounds, view).viewProjection.inverse();
    const float nx = float(2.0 * x / view.width - 1.0), ny = float(1.0 - 2.0 * y / view.height);
    auto unproject = [&](float z) {
        const Eigen::Vector4f p = inverse * Eigen::Vector4f(nx, ny, z, 1.0f);
        return Eigen::Vector3f(p.head<3>() / p.w());
    };
    const Eigen::Vector3f origin = unproject(-1.0f);
    const Eigen::Vector3f direction = (unproject(1.0f) - origin).normalized();
    float nearest = std::numeric_limits<float>::max();
    for (const auto& t : mesh.triangles) {
        // Moller-Trumbore, both faces (open surfaces are seen from either side).
        const Eigen::Vector3f& a = mesh.positions[t[0]];
        const Eigen::Vector3f e1 = mesh.positions[t[1]] - a, e2 = mesh.positions[t[2]] - a;
        const Eigen::Vector3f p = direction.cross(e2);
        const float det = e1.dot(p);
        if (std::abs(det) < 1e-12f)
            continue;
        const Eigen::Vector3f s = origin - a;
        const float u = s.dot(p) / det;
        if (u < 0.0f || u > 1.0f)
            continue;
        const Eigen::Vector3f q = s.cross(e1);
        const float v = direction.dot(q) / det;
        if (v < 0.0f || u + v > 1.0f)
            continue;
        const float distance = e2.dot(q) / det;
        if (distance > 0.0f && distance < nearest)
            nearest = distance;
    }
    if (nearest == std::numeric_limits<float>::max())
        return std::nullopt;
    return Eigen::Vector3f(origin + direction * nearest);
}

void SurfaceRenderer::setTextures(const TexturedMesh& mesh) {
    m_baseColour = uploadImage(mesh.baseColour, "base colour texture");
    m_normalMap = uploadImage(mesh.normalMap, "normal map");
    setMetallicRoughness(mesh);
}

void SurfaceRenderer::setMetallicRoughness(const TexturedMesh& mesh) {
    // A dry mesh binds one dry texel: the program's sampler always has a texture.
    m_wet = mesh.metallicRoughness.width > 0;
    const RgbaImage dry{1, 1, {{255, std::uint8_t(std::lround(kDryRoughness * 255.0f)), 0, 255}}};
    m_metallicRoughness =
        uploadImage(m_wet ? mesh.metallicRoughness : dry, "metallic-roughness texture");
}

SurfaceRenderer::SurfaceRenderer(const TexturedMesh& mesh)
    : m_baseColour(uploadImage(mesh.baseColour, "base colour texture")),
      m_normalMap(uploadImage(mesh.normalMap, "normal map")) {
    setMetallicRoughness(mesh);
    const std::size_t n = mesh.positions.size();
    if (mesh.normals.size() != n || mesh.tangents.size() != n || mesh.uvs.size() != n)
        throw std::invalid_argument("SurfaceRenderer: " + std::to_string(n) + " positions but " +
                                    std::to_string(mesh.normals.size()) + " normals, " +
                                    std::to_string(mesh.tangents.size()) + " tangents, " +
                                    std::to_string(mesh.uvs.size()) + " texture coordinates");
    for (const auto& t : mesh.triangles)
        for (const std::uint32_t v : t)
            if (v >= n)
                throw std::invalid_argument("SurfaceRenderer: vertex index " + std::to_string(v) +
                                            " out of range (" + std::to_string(n) + " vertices)");
    m_bounds = boundingSphere(mesh.positions);

    m_program =
        Program({embeddedShader("glsl/surface.vert")}, {embeddedShader("glsl/surface.frag")}, {});
    m_program.use();
    glUniform1i(m_program.uniform("uBaseColour"), kBaseColourUnit);
    glUniform1i(m_program.uniform("uNormalMap"), kNormalMapUnit);
    glUniform1i(m_program.uniform("uMetallicRoughness"), kMetallicRoughnessUnit);

    std::vector<float> interleaved;
    interleaved.reserve(n * kFloatsPerVertex);
    for (std::size_t i = 0; i < n; ++i) {
        interleaved.insert(interleaved.end(), mesh.positions[i].data(),
                           mesh.positions[i].data() + 3);
        interleaved.insert(interleaved.end(), mesh.normals[i].data(), mesh.normals[i].data() + 3);
        interleaved.insert(interleaved.end(), mesh.uvs[i].data(), mesh.uvs[i].data() + 2);
        interleaved.insert(interleaved.end(), mesh.tangents[i].data(), mesh.tangents[i].data() + 4);
    }
    m_vao.bind();
    glBindBuffer(GL_ARRAY_BUFFER, m_vertices.id());
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(interleaved.size() * sizeof(float)),
                 interleaved.data(), GL_STATIC_DRAW);
    const GLsizei stride = kFloatsPerVertex * sizeof(float);
    const int sizes[4] = {3, 3, 2, 4};
    std::size_t offset = 0;
    for (GLuint location = 0; location < 4; ++location) {
        glEnableVertexAttribArray(location);
        glVertexAttribPointer(location, sizes[location], GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<const void*>(offset * sizeof(float)));
        offset += std::size_t(sizes[location]);
    }
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, m_indices.id());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                 GLsizeiptr(mesh.triangles.size() * sizeof(mesh.triangles[0])),
                 mesh.triangles.data(), GL_STATIC_DRAW);
    m_indexCount = mesh.triangles.size() * 3;
    glBindVertexArray(0);
}

SurfaceImage SurfaceRenderer::render(const ViewOptions& view) const {
    if (view.width < 1 || view.height < 1 || view.width > kMaxSide || view.height > kMaxSide)
        throw InputError("resolution " + std::to_string(view.width) + "x" +
                         std::to_string(view.height) + " is out of range (1 to " +
                         std::to_string(kMaxSide) + " pixels per side)");
    GLint maxTexture = 0, maxRenderbuffer = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTexture);
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxRenderbuffer);
    const int limit = std::min(maxTexture, maxRenderbuffer);
    // Fewer samples per pixel rather than a failure when the GPU's limit is near.
    int s = std::max(1, view.supersample);
    while (s > 1 && std::max(view.width, view.height) * s > limit)
        --s;
    if (std::max(view.width, view.height) > limit)
        throw InputError("resolution " + std::to_string(view.width) + "x" +
                         std::to_string(view.height) + " exceeds this GPU's largest image (" +
                         std::to_string(limit) + " per side)");
    const int w = view.width * s, h = view.height * s;

    const Texture2D colour(w, h, GL_RGBA8);
    const Framebuffer framebuffer(colour);
    GLuint depthId = 0;
    glGenRenderbuffers(1, &depthId);
    const UniqueName<RenderbufferTraits> depth(depthId);
    glBindRenderbuffer(GL_RENDERBUFFER, depthId);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, w, h);
    framebuffer.bind();
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depthId);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        throw std::runtime_error("the " + std::to_string(w) + "x" + std::to_string(h) +
                                 " surface view framebuffer with depth is incomplete");
    }

    const Camera camera = cameraFor(m_bounds, view);
    glClearColor(view.background[0], view.background[1], view.background[2], view.background[3]);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    m_program.use();
    glUniformMatrix4fv(m_program.uniform("uViewProjection"), 1, GL_FALSE,
                       camera.viewProjection.data());
    glUniform3fv(m_program.uniform("uEye"), 1, camera.eye.data());
    glUniform3fv(m_program.uniform("uLight"), 1, camera.light.data());
    m_baseColour.bind(kBaseColourUnit);
    m_normalMap.bind(kNormalMapUnit);
    m_metallicRoughness.bind(kMetallicRoughnessUnit);
    glUniform1i(m_program.uniform("uWet"), m_wet ? 1 : 0);
    m_vao.bind();
    glDrawElements(GL_TRIANGLES, GLsizei(m_indexCount), GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
    glDisable(GL_DEPTH_TEST);

    std::vector<std::uint8_t> samples(std::size_t(w) * std::size_t(h) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, samples.data());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    // Box filter s x s samples per pixel; GL's row 0 is the bottom.
    SurfaceImage image;
    image.width = view.width;
    image.height = view.height;
    image.rgba.resize(std::size_t(view.width) * std::size_t(view.height) * 4);
    const int count = s * s;
    for (int y = 0; y < view.height; ++y)
        for (int x = 0; x < view.width; ++x)
            for (int k = 0; k < 4; ++k) {
                int sum = 0;
                for (int dy = 0; dy < s; ++dy)
                    for (int dx = 0; dx < s; ++dx)
                        sum += samples[(std::size_t(y * s + dy) * w + std::size_t(x * s + dx)) * 4 +
                                       std::size_t(k)];
                image.rgba[(std::size_t(view.height - 1 - y) * view.width + x) * 4 +
                           std::size_t(k)] = std::uint8_t((sum + count / 2) / count);
            }
    return image;
}

SurfaceImage renderSurface(const SurfaceTiles& tiles, const std::vector<float>& height,
                           const std::vector<std::array<std::uint8_t, 4>>& colours,
                           const ViewOptions& view, const SurfaceLook& look) {
    const SurfaceRenderer renderer(texturedSurface(tiles, height, colours, look));
    return renderer.render(view);
}

std::vector<SurfaceImage> renderTurntable(const SurfaceRenderer& renderer, const ViewOptions& view,
                                          int frames) {
    if (frames < 1)
        throw InputError("turntable frame count " + std::to_string(frames) + " must be at least 1");
    std::vector<SurfaceImage> images;
    for (int k = 0; k < frames; ++k) {
        ViewOptions frame = view;
        frame.azimuth = view.azimuth + 360.0 * k / frames;
        images.push_back(renderer.render(frame));
    }
    return images;
}

} // namespace morphogen::gl
