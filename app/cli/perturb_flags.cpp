#include "cli/perturb_flags.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "core/base/errors.hpp"
#include "core/domain/tile_sets.hpp"
#include "core/sim/local_regrowth.hpp"
#include "core/sim/local_relax.hpp"
#include "core/sim/localized_rd.hpp"
#include "core/sim/segments.hpp"
#include "core/surface/surface_perturb.hpp"

namespace morphogen::cli {

namespace {

std::array<double, 4> parseBall(const std::string& text) {
    std::array<double, 4> v{};
    std::istringstream in(text);
    std::string part;
    int n = 0;
    while (std::getline(in, part, ',')) {
        std::size_t used = 0;
        double x = 0;
        try {
            x = std::stod(part, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (n >= 4 || used == 0 || used != part.size() || !std::isfinite(x))
            throw InputError("--perturb '" + text +
                             "' is not accepted (X,Y,Z,R: four finite numbers, the centre in "
                             "mesh units and a radius R > 0)");
        v[std::size_t(n++)] = x;
    }
    if (n != 4 || !(v[3] > 0))
        throw InputError("--perturb '" + text +
                         "' is not accepted (X,Y,Z,R: four finite numbers, the centre in mesh "
                         "units and a radius R > 0)");
    return v;
}

} // namespace

void addPerturbFlags(CLI::App& command, PerturbFlags& flags) {
    command
        .add_option("--perturb", flags.ball,
                    "on a mesh: randomise the finished pattern within R (mesh units) of X,Y,Z, "
                    "then grow it back with localized RD")
        ->type_name("X,Y,Z,R");
}

void checkPerturbFlags(const PerturbFlags& flags, bool surface) {
    if (flags.ball.empty())
        return;
    parseBall(flags.ball);
    if (!surface)
        throw InputError("--perturb needs a mesh (--mesh or a session's \"surface\")");
}

namespace {

// Lo's distort: +-2 on the first chemical, enough to wipe the features there.
// Throws InputError naming --perturb when the ball reaches no texel.
SurfacePerturbation perturbation(const PerturbFlags& flags, const Session& session,
                                 const SurfaceSetup& setup) {
    const std::array<double, 4> ball = parseBall(flags.ball);
    return perturbSurface(setup.tiles, session.domain(),
                          Eigen::Vector3f(float(ball[0]), float(ball[1]), float(ball[2])),
                          float(ball[3]), 0, 2.0f, std::uint64_t(session.seed) + 1, "--perturb");
}

} // namespace

void checkPerturbBall(const PerturbFlags& flags, const Session& session,
                      const SurfaceSetup& setup) {
    if (!flags.ball.empty())
        perturbation(flags, session, setup);
}

void applyPerturbation(const PerturbFlags& flags, const Session& session, const SurfaceSetup& setup,
                       const SimulatorFactory& make, RunResult& result) {
    if (flags.ball.empty())
        return;
    const Atlas& atlas = *setup.tiles.atlas;
    const SurfacePerturbation p = perturbation(flags, session, setup);
    // As the run stepped: dt split into the weighted atlas's substeps.
    const Session running = segmentSessions(session).back();
    const int substeps = std::max(1, segmentsOf(session).back().substeps);
    std::unique_ptr<Simulator> sim = make(running);
    sim->setState(result.state);
    // The features under the ball erased (every chemical its mean there), then Lo's noise.
    for (const Brush& b :
         erasingBrushes(p, result.state, int(running.outputModel().chemicals().size())))
        sim->applyBrush(b);
    sim->applyBrush(p.brush);
    // The set grows where the change reaches its edge (local_regrowth.hpp):
    // Lo's step-counted growth went global on meshes before spots re-formed.
    // Thresholds, checks and the cap count session steps: a simulator step is
    // 1 / substeps of one, and a pattern drifting 2e-5 a session step moves
    // that much less a substep.
    LocalRegrowthOptions grow;
    grow.checkEvery *= substeps;
    grow.settledBelow /= float(substeps);
    grow.spreadAbove /= float(substeps);
    RelaxOptions relax;
    relax.checkEvery = grow.checkEvery;
    relax.settledBelow = grow.settledBelow;
    relax.maxSteps = int(std::min<long long>(static_cast<long long>(relax.maxSteps) * substeps,
                                             std::numeric_limits<int>::max() / 2));
    LocalRegrowth regrowth(std::make_shared<const TileNeighbourhoods>(atlas),
                           running.domain().sharedAtlas(), p.touched, grow);
    const RelaxResult r = relaxAdaptively(*sim, regrowth, relax);
    std::ostringstream os;
    os << "perturbed " << p.brush.region.cells().size() << " texels in " << p.touched.size()
       << " tiles; localized RD " << (r.settled ? "re-settled" : "did not re-settle") << " after "
       << r.iterations / substeps << " session steps (" << r.iterations << " steps of dt/"
       << substeps << "), " << r.seconds << " s; phases it/s (tiles):";
    for (const RelaxPhase& phase : r.phases)
        os << " " << (phase.phase ? "A" + std::to_string(phase.phase) : std::string("global"))
           << " " << long(std::lround(phase.iterationsPerSecond())) << " (" << phase.tiles << ")";
    os << (r.global ? "; went global" : "") << " of " << atlas.tileCount() << " tiles";
    std::fprintf(stderr, "morphogen: %s\n", os.str().c_str());
    if (!result.settled)
        std::fprintf(stderr, "morphogen: note: the run had not settled before --perturb; tiles "
                             "outside the active set kept their unsettled values\n");
    result.state = sim->takeState();
}

} // namespace morphogen::cli
