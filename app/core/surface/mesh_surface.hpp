#pragma once

#include <memory>

#include "core/session/surface_geometry.hpp"
#include "core/surface/surface_setup.hpp"
#include "core/surface/surface_weights.hpp"

namespace morphogen {

// A session's surface as the run sees it (SurfaceGeometry): the mesh and its
// tiles, and the weight options they were built with, so a deformation
// (Lo 5.5: stretchSurface) recomputes the metric as setUpSurface did.
// Immutable: a deformation makes a new one, so undo and the growth history
// keep the surface each moment had.
class MeshSurface final : public SurfaceGeometry {
public:
    MeshSurface(std::shared_ptr<const SurfaceSetup> setup, const SurfaceWeightOptions& options);

    DeformedSurface deformed(const DeformSpec& spec) const override;
    double unitsPerMesh() const override;

    const std::shared_ptr<const SurfaceSetup>& setup() const { return m_setup; }

private:
    std::shared_ptr<const SurfaceSetup> m_setup;
    SurfaceWeightOptions m_options; // featureScale unset: taken from m_setup when used
};

// The texel centres of tiles as a session's atlasPositions holds them.
std::shared_ptr<const std::vector<std::array<float, 3>>>
texelPositionsOf(const SurfaceTiles& tiles);

} // namespace morphogen
