#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/base/state.hpp"
#include "core/operators/diffusion_operator.hpp"
#include "core/session/session.hpp"
#include "core/sim/brush.hpp"

namespace morphogen {

// -1 for every chemical: no diffusion rate comes from a param map.
constexpr std::array<int, kMaxChemicals> noMappedRates() {
    std::array<int, kMaxChemicals> rates{};
    for (int& r : rates)
        r = -1;
    return rates;
}

// What one step needs, derived once from a session; both backends read the
// same values so they share step semantics. Explicit Euler:
//   c' = clamp(c + dt * (react(c) + A c), clampMin, clampMax)
// Semi-implicit: relaxation passes on (I - dt A) c' = c + dt react(c),
// starting from c, clamped after every sweep.
struct StepConstants {
    int chemicals = 0;
    float dt = 1.0f;
    std::array<float, kMaxChemicals> clampMin = {};
    std::array<float, kMaxChemicals> clampMax = {};
    std::vector<float> params; // model declaration order
    Domain domain;
    DiffusionOperator op;
    Integrator integrator = Integrator::ExplicitEuler;
    int relaxationPasses = 8;
    // SemiImplicit: each chemical's Richardson weight (stability.hpp); a sweep is
    //   x' = clamp(x + omega (rhs - x + dt A x)),  rhs = c + dt f(c).
    std::array<float, kMaxChemicals> omega = {};
    double contraction = 0; // worst chemical's residual factor per sweep
    // Weighted atlas: each chemical's own (0 where it does not diffuse); see
    // chemicalRelaxationPasses.
    std::array<double, kMaxChemicals> chemicalContraction = {};

    // Parameters that vary per cell (the session's param_maps), at most 4:
    // their indices in `params` and one plane of values per cell each.
    std::vector<int> mappedParams;
    State paramMaps;
    // Per chemical: the mapped parameter (index into mappedParams) that is its
    // diffusion rate, or -1. The operator is then compiled at rate 1 and the
    // backends multiply its result by the cell's rate.
    std::array<int, kMaxChemicals> mappedRate = noMappedRates();

    // TiledGrid (a batched sweep): every tile's full parameter vector, tile
    // (tx, ty) at (ty * columns + tx) * params.size(), ty counted from the top
    // as rows are stored. The swept ones are also in paramMaps, constant per
    // tile, for the GPU and the generic CPU path; the fused CPU kernels read
    // this table instead, one tile segment of a row at a time.
    std::vector<float> tileParams;

    // Weighted atlas: the coefficients as four planes (+x, +y, -x, -y, each
    // cellCount floats; coefficientPlanes in atlas_weights.hpp), shared by
    // copies. Null otherwise. The 5-point term of a texel is then
    //   rate * ((c_-x u_-x + c_+x u_+x + c_-y u_-y + c_+y u_+y) - S u),
    //   S = ((c_-x + c_+x) + c_-y) + c_+y,
    // summed in that order on both backends, which with every c = 1 is the
    // unweighted stencil's (l + r + d + u) - 4 u bit for bit.
    std::shared_ptr<const std::vector<float>> weightPlanes;
    // Weighted atlas whose weights have diagonals (AtlasWeights::diagonal): their
    // four planes ((-x,-y), (+x,-y), (-x,+y), (+x,+y)), else null. The term above
    // then also has
    //   + ((k_0 u_0 + k_1 u_1) + (k_2 u_2 + k_3 u_3)) on the sides and
    //   S + ((k_0 + k_1) + (k_2 + k_3)) as the centre's sum,
    // on both backends; op.form stays Laplacian5 (the weights are the stencil).
    std::shared_ptr<const std::vector<float>> diagonalPlanes;
    // A 9-point stencil was asked for on a weighted atlas whose weights have no
    // diagonals: the weighted 5-point runs (op.form is Laplacian5), and
    // describePlan says so.
    bool nineToFivePoint = false;
    // Anisotropic diffusion on a surface (AtlasWeights::tensor, an anisotropic
    // session on a mesh): the 16 planes of its two operators L1, L2
    // (tensorPlanes: links then diagonals of each), and per chemical its mix
    // (p, q1, q2) (tensorMix, the chemical's rate included). Chemical c's term
    // is then p S(u) + q1 L1(u) + q2 L2(u), S the weighted term above without
    // the rate, each of the three summed as S is; op.form is Laplacian5.
    std::shared_ptr<const std::vector<float>> tensorPlanes;
    std::vector<std::array<float, 3>> tensorMixes;

    // Water drops on a model (AtlasWeights::drift): its five planes (inflow
    // +x, +y, -x, -y, outflow; driftPlanes in atlas_weights.hpp), else null.
    // Chemical c drifts when drifts[c] is 1 (the model lets it diffuse): its
    // term gains ((in_-x u_-x + in_+x u_+x) + in_-y u_-y) + in_+y u_+y - out u,
    // added after the diffusion term, on both backends.
    std::shared_ptr<const std::vector<float>> driftPlanes;
    std::array<float, kMaxChemicals> drifts = {};
    // Gravity's carrier (Gravity::carrier), else -1: every u above is then
    // m(w) u with w the carrier at that texel and m(w) = max(w, 0) / (max(w,
    // 0) + driftCling), so thin water clings and deep water runs.
    int driftCarrier = -1;
    float driftCling = 0.0f;

    bool weighted() const { return weightPlanes != nullptr; }
    bool drifting() const { return driftPlanes != nullptr; }
    bool tensorWeighted() const { return tensorPlanes != nullptr; }
    bool crossWeighted() const { return diagonalPlanes != nullptr; }
    bool hasParamMaps() const { return !mappedParams.empty(); }
    bool tiled() const { return domain.kind() == DomainKind::TiledGrid; }
    // Whether every per-cell parameter is constant per tile and none is a
    // diffusion rate: the fused kernels then run with one parameter set per tile.
    bool paramsPerTileOnly() const;
    const float* tileParamsAt(int tx, int ty) const {
        return tileParams.data() +
               (std::size_t(ty) * std::size_t(domain.columns()) + std::size_t(tx)) * params.size();
    }

    // Throws InputError for combinations the backends cannot run.
    static StepConstants fromSession(const Session& session);
};

// Per chemical of an anisotropic session, its tensor's mix (tensorMix) at
// `rates` (one per chemical; null: rate 1), for AtlasTensorWeights.
std::vector<std::array<float, 3>> sessionTensorMixes(const Session& session, const float* rates);

// One simulation backend. Runs steps without reading back; state() reads back.
class Simulator {
public:
    virtual ~Simulator() = default;
    virtual std::string backendName() const = 0;
    virtual void setState(const State& state) = 0;
    virtual State state() const = 0;
    // The state, leaving the simulator without one: it must be given one
    // (setState) before it runs again. A big render's last read-back: the
    // CPU backend hands over its buffer and frees its scratch (no copy).
    virtual State takeState() { return state(); }
    // findInsaneValue of the current state, read in place (CPU) or a band of
    // rows at a time (GPU): a blow-up check makes no whole copy of the state.
    virtual std::optional<std::string> insaneValue(const ReactionModel& model) const;
    virtual void run(int steps) = 0;
    // Cells marked 1 keep their values exactly (still feeding their
    // neighbours' diffusion); empty: none. Turk's cascades.
    virtual void setFrozen(const std::vector<std::uint8_t>& frozen) = 0;
    // Writes one brush stroke between steps: only the region's cells change
    // (the GPU draws over the region's rectangles; nothing is read back or
    // re-uploaded whole). Throws InputError for a brush the model rejects
    // (checkBrush), and leaves the simulation unchanged then.
    virtual void applyBrush(const Brush& brush) = 0;
    // Localized reaction-diffusion (core/sim/localized_rd.hpp): from the next
    // step only the texels of these atlas tiles step; every other texel keeps
    // its value exactly and still serves as a neighbour. Empty: every tile
    // (the default). Throws InputError for a tile out of range or a domain
    // that is not an atlas (with a non-empty set), and leaves the set as it was.
    // A semi-implicit step solves on the active tiles alone (their neighbours
    // held), except on the CPU with per-cell reaction parameters, where it
    // keeps stepping every tile: an explicit step of a few tiles would be
    // unstable at its dt.
    virtual void setActiveTiles(const std::vector<int>& tiles) = 0;

    // Live changes, in force from the next step, without a rebuild or a
    // read-back: the GPU updates uniforms, the CPU its StepConstants.
    // `params` holds every parameter of the model (Session::params); mapped
    // parameters keep their per-cell maps. The caller validates the values.
    void setParams(const ParamValues& params) {
        Session next = liveSession();
        next.params = params;
        applyLiveChange(std::move(next));
    }
    void setDt(float dt) {
        Session next = liveSession();
        next.dt = dt;
        applyLiveChange(std::move(next));
    }

    // The value parameter `name` has at cell (x, y), row 0 at the top, where it
    // varies per cell (a param map, one painted with the brush, a sweep's
    // tiles); nullopt where it is uniform (Session::params holds it then).
    std::optional<float> cellParam(const std::string& name, int x, int y) const;

protected:
    // The session the simulator runs now (live changes and painted maps applied).
    virtual const Session& liveSession() const = 0;
    // The constants the steps run with, painted maps included.
    virtual const StepConstants& stepConstants() const = 0;
    // Takes a session that differs from liveSession() in params or dt only.
    virtual void applyLiveChange(Session next) = 0;
};

// The relaxation passes chemical c gets in a semi-implicit step on a weighted
// atlas: as many as leave it the residual the slowest chemical has after all
// of k.relaxationPasses (contraction_c^p <= contraction^passes), at least one
// (a chemical that does not diffuse takes its right-hand side in one pass).
// A chemical that diffuses slowly converges in fewer passes: Meinhardt's
// activators (rate 0.003) in one where his substrates (0.2) take eight. Elsewhere
// every chemical gets k.relaxationPasses. `passes` in place of
// k.relaxationPasses: the same rule for another count.
int chemicalRelaxationPasses(const StepConstants& k, int chemical);
int chemicalRelaxationPasses(const StepConstants& k, int chemical, int passes);

// The constants a live change of parameters or dt alters (params, dt, the
// operator's rates, kernels and map coefficients, the semi-implicit weights),
// recomputed for `session`, which differs from the one k was made from only in
// params and dt. The operator's form, maps and integrator stay, and it returns
// true; false when the new rates need another operator form (a generalized
// kernel growing from 3x3 to 5x5 as a rate leaves 0): k is then replaced
// whole and the backend must rebuild its step.
bool updateLiveConstants(StepConstants& k, const Session& session);

// setActiveTiles' check: the set ascending without repeats; throws InputError
// as setActiveTiles says.
std::vector<int> checkActiveTiles(const Domain& domain, const std::vector<int>& tiles);

} // namespace morphogen
