#include "core/surface/mesh_surface.hpp"

#include <cmath>

#include "core/base/errors.hpp"
#include "core/domain/atlas_weights.hpp"
#include "core/surface/surface_deform.hpp"

namespace morphogen {

MeshSurface::MeshSurface(std::shared_ptr<const SurfaceSetup> setup,
                         const SurfaceWeightOptions& options)
    : m_setup(std::move(setup)), m_options(options) {
    m_options.featureScale = nullptr;
}

std::shared_ptr<const std::vector<std::array<float, 3>>>
texelPositionsOf(const SurfaceTiles& tiles) {
    auto positions = std::make_shared<std::vector<std::array<float, 3>>>();
    positions->reserve(tiles.texelPositions.size());
    for (const Eigen::Vector3f& p : tiles.texelPositions)
        positions->push_back({p.x(), p.y(), p.z()});
    return positions;
}

double MeshSurface::unitsPerMesh() const {
    return m_setup->unitsPerWorld;
}

DeformedSurface MeshSurface::deformed(const DeformSpec& spec) const {
    SlabStretch stretch;
    stretch.centre =
        Eigen::Vector3f(float(spec.centre[0]), float(spec.centre[1]), float(spec.centre[2]));
    stretch.direction = Eigen::Vector3f(float(spec.direction[0]), float(spec.direction[1]),
                                        float(spec.direction[2]));
    stretch.radius = float(spec.radius);
    stretch.factor = float(spec.factor);
    stretch.reach = float(spec.reach);
    auto copy = std::make_shared<SurfaceSetup>(*m_setup);
    DeformedSurface d;
    d.deformedTiles = stretchSurface(copy->tiles, copy->mesh.mesh, stretch);
    if (d.deformedTiles.empty())
        throw InputError("deformation: the slab of half width " + std::to_string(spec.radius) +
                         " round the centre" +
                         (spec.reach > 0
                              ? " (within " + std::to_string(stretch.reach + stretch.fadeWidth()) +
                                    " of its axis)"
                              : std::string()) +
                         " holds no tile of the surface");
    SurfaceWeightOptions options = m_options;
    if (!copy->featureScale.empty())
        options.featureScale = &copy->featureScale;
    copy->weights = std::make_shared<const AtlasWeights>(surfaceWeights(copy->tiles, options));
    d.weights = copy->weights;
    d.positions = texelPositionsOf(copy->tiles);
    d.geometry = std::make_shared<const MeshSurface>(copy, m_options);
    return d;
}

} // namespace morphogen
