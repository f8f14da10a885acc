#pragma once

#include <array>
#include <memory>
#include <vector>

namespace morphogen {

struct AtlasWeights;

// A deformation of a session's surface (Lo et al. section 5.5) as a live
// edit records it: the slab |(p - centre) . direction| <= radius of the mesh
// (its own coordinates and units) stretched along `direction` by `factor`
// (below 1 compresses); the mesh outside the slab moves rigidly. With a
// reach (> 0) only the part of the slab within that distance of its axis
// stretches, fading out beyond it (SlabStretch::fadeWidth): a local stretch
// that leaves the rest of the model where it was.
struct DeformSpec {
    std::array<double, 3> centre = {0, 0, 0};
    std::array<double, 3> direction = {1, 0, 0};
    double radius = 0.2;
    double factor = 1.5;
    double reach = 0; // 0: the whole slab across the model

    bool operator==(const DeformSpec& o) const {
        return centre == o.centre && direction == o.direction && radius == o.radius &&
               factor == o.factor && reach == o.reach;
    }
};

struct DeformedSurface;

// A session's surface geometry, for deformations while it runs: the engine's
// run (core/sim) changes the surface through this interface without
// depending on the mesh pipeline (core/surface implements it: MeshSurface).
class SurfaceGeometry {
public:
    virtual ~SurfaceGeometry() = default;
    // A deformed copy and what the run needs of it. Throws InputError for a
    // deformation that touches no tile or has bad numbers.
    virtual DeformedSurface deformed(const DeformSpec& spec) const = 0;
    // Model units per mesh unit (the session's scale on this surface): what
    // fields laid out in model units (noise param maps) scale mesh points by.
    virtual double unitsPerMesh() const = 0;
};

struct DeformedSurface {
    std::shared_ptr<const SurfaceGeometry> geometry;
    std::shared_ptr<const AtlasWeights> weights;                        // the deformed metric's
    std::shared_ptr<const std::vector<std::array<float, 3>>> positions; // texel centres
    std::vector<int> deformedTiles; // tiles whose shape changed, ascending
};

} // namespace morphogen
