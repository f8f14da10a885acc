#pragma once

#include <functional>
#include <memory>
#include <string>

#include "core/domain/atlas_weights.hpp"
#include "core/mesh/mesh_io.hpp"
#include "core/session/session.hpp"
#include "core/surface/surface_tiles.hpp"

namespace morphogen {

// A session's mesh, read: "sample:NAME" generates a sample (mesh_samples.hpp,
// its default detail, the same mesh as models/meshes/NAME.obj), anything else
// is a file relative to `baseDir`. Throws InputError naming the file or sample.
LoadedMesh loadSurfaceMesh(const SurfaceSpec& spec, const std::string& baseDir);

// Everything a surface run needs beside the session: the mesh, its tiles with
// their geometry, and the diffusion weights the engine runs with.
struct SurfaceSetup {
    LoadedMesh mesh; // the full-resolution mesh
    SurfaceTiles tiles;
    std::shared_ptr<const AtlasWeights> weights;
    std::vector<float> featureScale; // per cell, curvature scaling (empty: none)
    double unitsPerWorld = 1;        // model units per mesh unit
    double texelUnits = 0;           // mean texel side, model units
    double seconds = 0;              // mesh to atlas, wall clock
    // The explicit substeps the weights would need, and whether the session
    // was switched to semi-implicit steps for them (chooseSurfaceIntegrator).
    int explicitSubsteps = 1;
    bool switchedToSemiImplicit = false;

    // Several lines for the report: the mesh, tiles, atlas, scale, time.
    std::string describe() const;
};

// The texel side an automatic tile size aims at, in model units: a little
// finer than a flat canvas's one cell per unit, so the tiles' uneven sizes
// stay resolved where they are largest.
constexpr double kSurfaceTexelUnits = 0.75;

// A surface session that did not choose its integrator (Session::
// integratorGiven) runs semi-implicit when its explicit step would take more
// substeps than a semi-implicit step's relaxation passes and one more (a
// pass costs about what an explicit substep does on the CPU): the few
// smallest texels set the explicit step for every texel, a Jacobi pass is
// stable at any dt. Only where the semi-implicit step runs: isotropic weights
// without drops, no diffusion rate from a param map (in any stage's model).
// Returns the explicit substeps; `switched` tells whether it changed.
int chooseSurfaceIntegrator(Session& session, const AtlasWeights& weights, bool* switched);

// Loads the session's mesh, builds its tiles (automatic tile size: texels of
// about kSurfaceTexelUnits for the session's length; automatic budget:
// automaticTileBudget) and weights, and sets the session to run on the atlas
// (useAtlas) with chooseSurfaceIntegrator's integrator. The session's length is the square root of
// the model's area in model units (a session without one takes its width). `progress` gets the
// phase names and fractions. Throws InputError for a mesh that cannot be used.
SurfaceSetup setUpSurface(Session& session,
                          const std::function<void(const std::string&, double)>& progress = {});

} // namespace morphogen
