#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace morphogen {

// A material of the model's file, kept when a pattern is baked into the
// model's own UVs: the pattern becomes its base colour and normal map, and
// what the artist set besides (name, metalness, roughness, emission,
// transparency, sidedness) stays. glTF's metallic-roughness fields and
// defaults.
struct MeshMaterial {
    std::string name;
    double baseColourAlpha = 1.0; // the factor's alpha; its colour is the pattern's
    double metallic = 1.0;
    double roughness = 1.0;
    std::array<double, 3> emissive = {0, 0, 0};
    std::string alphaMode = "OPAQUE"; // OPAQUE, MASK or BLEND
    double alphaCutoff = 0.5;
    bool doubleSided = false;
};

// Materials and, per triangle, the index of its material (-1: none named;
// the exporter's own then). Empty when the file names none.
struct MeshMaterials {
    std::vector<MeshMaterial> materials;
    std::vector<std::int32_t> ofTriangle;
};

} // namespace morphogen
