#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/surface/textured_surface.hpp"

namespace morphogen {

// Writes a TexturedMesh as a binary glTF 2.0 file: one mesh of one triangle
// primitive (uint32 indices; POSITION with its min and max, NORMAL,
// TEXCOORD_0, TANGENT), one material (baseColorTexture = the colour-mapped
// pattern, normalTexture = the baked relief, metallic 0, double-sided, and
// metallicRoughnessTexture where the mesh has one: wet water drops), the
// textures PNG images stored in the binary chunk (mimeType image/png) with a
// clamped, linearly filtered sampler. Every buffer view is 4-byte aligned and
// inside the buffer. Atomic (a temporary renamed into place; an OutputFiles
// stage path is written in place). Throws InputError naming the path when it
// cannot be written, std::invalid_argument for an inconsistent mesh.
void writeTexturedGlb(const TexturedMesh& mesh, const std::string& path);

// texturedSurface, then writeTexturedGlb: the tiled surface re-textured with
// the result (`colours` and `height` per atlas cell, as texturedSurface).
void exportSurfaceGlb(const SurfaceTiles& tiles, const std::vector<float>& height,
                      const std::vector<std::array<std::uint8_t, 4>>& colours,
                      const std::string& path, const SurfaceLook& look = {});

// Reads back a GLB that writeTexturedGlb wrote (or any GLB of one textured
// triangle primitive with those attributes, float attributes and 8-bit
// RGB/RGBA PNG textures; several primitives on the same vertices, one per
// material, come back as one mesh with its materials): for tests and for drawing an exported model
// with the same renderer. Throws InputError naming the file and what is missing.
TexturedMesh readTexturedGlb(const std::string& path);

} // namespace morphogen
