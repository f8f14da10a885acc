#include "core/sim/session_run.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include "core/base/errors.hpp"
#include "core/base/memory_budget.hpp"
#include "core/base/names.hpp"
#include "core/domain/atlas.hpp"
#include "core/domain/atlas_weights.hpp"
#include "core/models/initial_condition.hpp"
#include "core/numerics/resample.hpp"
#include "core/operators/stability.hpp"
#include "core/session/cascade.hpp"
#include "core/sim/initial_state.hpp"
#include "core/sim/localized_rd.hpp"
#include "core/sim/simulator.hpp"
#include "core/sim/stroke_brush.hpp"

namespace morphogen {

namespace {

// The least a run needs: at its largest segment, the state and the next
// state a step writes (every backend holds both; the GPU's textures and the
// CPU's buffers add more, measured by `bench`'s memory rows). Refused up
// front when even that cannot be had.
void requireRunMemory(const std::vector<Segment>& segments) {
    std::uint64_t most = 0;
    const Session* largest = nullptr;
    for (const Segment& s : segments) {
        const std::uint64_t bytes =
            std::uint64_t(s.session.width) * std::uint64_t(s.session.height) *
            s.session.reactionModel().chemicals().size() * sizeof(float) * 2;
        if (bytes >= most) {
            most = bytes;
            largest = &s.session;
        }
    }
    if (!largest)
        return;
    const std::string what =
        "a " + std::to_string(largest->width) + "x" + std::to_string(largest->height) +
        " grid of " + std::to_string(largest->reactionModel().chemicals().size()) + " chemicals";
    setCurrentWorkload(what + " (" + formatBytes(most) + " for two copies of its state)");
    requireMemory(most, "the run (" + what + ")");
}

} // namespace

SessionRun::SessionRun(const Session& session, SimulatorFactory makeSimulator, int checkEvery)
    : m_session(session), m_make(std::move(makeSimulator)), m_checkEvery(std::max(0, checkEvery)),
      m_segments(segmentsOf(session)), m_stateModel(&session.reactionModel()) {
    for (const Segment& s : m_segments)
        m_totalSteps += s.session.steps; // segmentsOf keeps the total within an int
    requireRunMemory(m_segments);
    enterSegment(0);
    applyDueEdits();
}

void SessionRun::enterSegment(std::size_t i) {
    m_index = i;
    m_stepsRun.push_back(0);
    m_entry = m_segments[i];
    m_strokeCoverage.clear(); // cell indices of the last segment's grid
    m_regrowth.reset();       // the new simulator steps every tile
    const Segment& segment = m_segments[i];
    const Session& part = segment.session;
    const ReactionModel& model = part.reactionModel();
    if (i == 0)
        m_state = initialState(part); // a tiled domain starts every tile on its own

    else if (m_state.width() != part.width || m_state.height() != part.height) {
        if (!m_frozen.empty())
            m_frozen =
                resampleMask(m_frozen, m_state.width(), m_state.height(), part.width, part.height);
        m_state = resampleBilinear(m_state, part.width, part.height, part.edges);
    }
    // The rule reads the previous stage's result, with that stage's model.
    if (segment.freeze)
        m_frozen = applyFreezeRule(*segment.freeze, m_state, *m_stateModel, std::move(m_frozen));
    if (segment.newModel && i > 0) {
        // A new model: a fresh start of its own; only the frozen mask carries over.
        m_state = makeInitialState(part.init, model, part.params, part.width, part.height,
                                   part.seed, part.layoutCellSize());
        m_stateModel = &model;
    }
    if (!segment.reset.empty() && !m_frozen.empty())
        resetFrozenCells(m_state, m_frozen, segment.reset, model);

    m_simulator.reset(); // a GPU simulator's textures go before the next one's are made
    m_simulator = m_make(part);
    m_simulator->setState(m_state);
    m_simulator->setFrozen(m_frozen);
    // Segments of no steps (a stage that only freezes or resets) are done as
    // soon as they are entered.
    if (part.steps == 0 && i + 1 == m_segments.size() && !m_session.edits.empty()) {
        // A session that ends here may still hold edits for its end (strokes
        // on a canvas saved before any step ran).
        applyDueEdits();
        finishSegment(m_simulator->takeState());
    } else if (part.steps == 0)
        finishSegment(m_state);
    else
        m_state = State(); // the simulator holds it now: one copy of the state, not two
}

void SessionRun::finishSegment(State state) {
    m_state = std::move(state);
    if (m_index + 1 < m_segments.size()) {
        enterSegment(m_index + 1);
    } else {
        m_finished = true;
        m_simulator.reset(); // its buffers or textures: the state is in m_state now
    }
}

int SessionRun::segmentRemaining() const {
    return m_finished ? 0 : m_segments[m_index].session.steps - m_stepsRun[m_index];
}

namespace {

// Whether `part`'s time step is within what its diffusion allows (semi-implicit
// steps are stable at any dt; explicit ones up to 0.8 of the spectral limit,
// the margin suggestDt keeps for the reaction's own stiffness).
bool timeStepWithinLimit(const Session& part) {
    if (part.integrator == Integrator::SemiImplicit)
        return true;
    const ExplicitStability s = explicitStability(compileDiffusion(part), part.domain(), part.dt);
    return s.maxStableDt && part.dt <= 0.8 * *s.maxStableDt;
}

// The strokes that put chemicals in (add, set, randomise) among `applied`.
struct StrokeTally {
    int count = 0;
    long long lastStep = -1;
    float largest = 0;
};

StrokeTally strokesApplied(const std::vector<LiveEdit>& applied) {
    StrokeTally t;
    for (const LiveEdit& e : applied)
        if (e.stroke && !e.stroke->chemical.empty() && e.stroke->mode != BrushMode::Remove &&
            e.stroke->mode != BrushMode::Paint) {
            ++t.count;
            t.lastStep = e.step;
            t.largest = std::max(t.largest, std::abs(e.stroke->value));
        }
    return t;
}

} // namespace

void SessionRun::checkBlowUp(int before) const {
    const Session& part = segmentSession();
    auto problem = m_simulator->insaneValue(part.reactionModel());
    if (!problem)
        return;
    const int done = m_stepsRun[m_index];
    const float dt = suggestDt(part);
    std::ostringstream os;
    os << "the simulation blew up between step " << before + 1 << " and step " << done;
    if (m_segments.size() > 1)
        os << " of " << (m_session.stages.empty() ? "level " : "stage ") << m_index + 1;
    os << " (" << *problem << ", backend " << m_simulator->backendName() << ", dt " << part.dt
       << ")";
    // Strokes pile chemicals up where they overlap; past the model's range
    // its reaction can run away at any time step. Say so rather than blame dt
    // when dt is within its limit.
    const StrokeTally strokes = strokesApplied(m_applied);
    const bool dtWithin = timeStepWithinLimit(part);
    if (strokes.count > 0 && dtWithin) {
        os << "; the time step is within its stability limit, so it is not the cause: "
           << strokes.count << (strokes.count == 1 ? " stroke" : " strokes")
           << " put chemicals in before it (the last at step " << strokes.lastStep
           << ", amounts up to " << strokes.largest
           << "), and where strokes pile up the values leave the range the reaction stays "
              "bounded in: paint fewer or weaker strokes (a smaller value), or 'set' a "
              "value instead of adding to it";
    } else {
        os << "; try a smaller time step such as --dt " << dt;
        if (strokes.count > 0)
            os << " (" << strokes.count << (strokes.count == 1 ? " stroke" : " strokes")
               << " also put chemicals in before it: where strokes pile up, fewer or weaker "
                  "ones help too)";
    }
    throw BlowUpError(os.str(), done, dt);
}

void SessionRun::setSettleCheck(int every, int after, std::function<bool(const State&)> settled) {
    std::size_t own = 0;
    while (own + 1 < m_segments.size() && !m_segments[own + 1].refine)
        ++own;
    const int substeps = m_segments[own].substeps;
    m_settleEvery = settled ? std::max(0, every) * substeps : 0;
    m_settleAfter = std::max(0, after) * substeps;
    m_settled = std::move(settled);
}

bool SessionRun::inSettleSegment() const {
    if (m_settleEvery <= 0 || m_finished)
        return false;
    const bool lastOwn = m_index + 1 == m_segments.size() || m_segments[m_index + 1].refine;
    return lastOwn && !m_segments[m_index].refine;
}

int SessionRun::advance(int steps) {
    int run = 0;
    while (run < steps && !m_finished) {
        // Edits due at a segment boundary apply in the segment just entered.
        applyDueEdits();
        const int done = m_stepsRun[m_index];
        const int length = m_segments[m_index].session.steps;
        // Stop at the next blow-up check, as runSimulation's chunks do, and
        // at the next recorded edit.
        int n = std::min({steps - run, length - done, stepsToNextEdit()});
        if (m_checkEvery > 0)
            n = std::min(n, m_checkEvery - done % m_checkEvery);
        const bool settling = inSettleSegment();
        if (settling)
            n = std::min(n, m_settleEvery - done % m_settleEvery);
        if (m_regrowth)
            n = std::min(n, m_regrowth->stepsBeforeChange());
        m_simulator->run(n);
        if (m_regrowth)
            afterRegrowthSteps(n);
        m_stepsRun[m_index] += n;
        m_stepsDone += n;
        run += n;
        const int now = m_stepsRun[m_index];
        const bool end = now == length;
        const bool blowUpCheck = m_checkEvery > 0 && now % m_checkEvery == 0;
        const bool settleCheck = settling && !end && now % m_settleEvery == 0;
        // The session's last step: edits recorded at its end (a stroke after
        // the last step a designer ran) apply before the result is taken.
        if (end && m_index + 1 == m_segments.size())
            applyDueEdits();
        if (end || blowUpCheck || settleCheck) {
            const int before = m_checkEvery > 0 ? (now - 1) / m_checkEvery * m_checkEvery : 0;
            checkBlowUp(before);
            if (settleCheck && now >= m_settleAfter && m_settled(m_simulator->state())) {
                m_settledEarly = true;
                finishSegment(m_simulator->takeState());
            } else if (end) {
                finishSegment(m_simulator->takeState());
            }
        }
    }
    // Edits due where the run stopped apply now: a run paused there (a
    // designer that replayed a saved session to its last step) holds them,
    // and its completed() records them.
    applyDueEdits();
    return run;
}

void SessionRun::setColormap(const ColorMapSpec& colormap) {
    m_session.colormap = colormap;
    for (Segment& segment : m_segments)
        segment.session.colormap = colormap;
    m_entry.session.colormap = colormap;
}

long long SessionRun::segmentStartStep() const {
    long long steps = 0;
    for (std::size_t i = 0; i < m_index && i < m_stepsRun.size(); ++i)
        steps += m_stepsRun[i] / m_segments[i].substeps;
    return steps;
}

long long SessionRun::sessionStepsDone() const {
    return segmentStartStep() + m_stepsRun[m_index] / m_segments[m_index].substeps;
}

int SessionRun::stepsToNextEdit() const {
    const std::vector<LiveEdit>& own = m_session.edits;
    if (m_nextEdit >= own.size())
        return std::numeric_limits<int>::max();
    const long long target =
        (own[m_nextEdit].step - segmentStartStep()) * m_segments[m_index].substeps;
    const long long left = target - m_stepsRun[m_index];
    // Past the segment's end the segment length stops the chunk first.
    return left > 0 ? int(std::min<long long>(left, std::numeric_limits<int>::max()))
                    : std::numeric_limits<int>::max();
}

void SessionRun::applyDueEdits() {
    const std::vector<LiveEdit>& own = m_session.edits;
    if (m_finished || m_nextEdit >= own.size() || m_stepsRun[m_index] % substeps() != 0)
        return;
    const long long now = sessionStepsDone();
    while (m_nextEdit < own.size() && own[m_nextEdit].step <= now) {
        applyNow(own[m_nextEdit]);
        m_applied.push_back(own[m_nextEdit]);
        ++m_nextEdit;
    }
}

void SessionRun::applyNow(const LiveEdit& edit, bool follow) {
    // A deformation first: worked out before anything changes (it may be
    // refused), and its rebuild replays the edits before this one.
    std::vector<int> deformed;
    if (edit.deform) {
        const DeformedSurface d = deformSurface(*edit.deform);
        useDeformedSurface(d);
        deformed = d.deformedTiles;
    }
    if (!edit.params.empty())
        setParams(edit.params);
    if (edit.dt)
        setDt(*edit.dt);
    std::optional<Brush> written;
    if (edit.stroke) {
        written = strokeWrite(*edit.stroke);
        m_simulator->applyBrush(*written);
    }
    if (follow)
        followEdit(edit, written ? &*written : nullptr, deformed);
}

void SessionRun::followEdit(const LiveEdit& edit, const Brush* written,
                            const std::vector<int>& deformed) {
    // New parameters or dt change the whole pattern: every tile steps.
    const bool localStroke = edit.stroke && edit.stroke->localized;
    if (!edit.params.empty() || edit.dt || (edit.stroke && !localStroke) ||
        (!edit.stroke && !edit.deform)) {
        endRegrowth();
        return;
    }
    const Atlas* atlas = segmentSession().domain().atlasMap();
    if (!atlas) // localized strokes and deformations are on a surface: there is an atlas
        return;
    std::vector<int> touched = deformed;
    if (written) {
        const std::vector<int> stroked = touchedTiles(*atlas, written->region);
        touched.insert(touched.end(), stroked.begin(), stroked.end());
        std::sort(touched.begin(), touched.end());
        touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    }
    if (touched.empty())
        return; // a piece that changed nothing (its path covered already)
    if (m_regrowth) {
        m_regrowth->touch(touched);
    } else {
        if (m_neighbourhoodsOf != atlas) {
            m_neighbourhoods = std::make_shared<const TileNeighbourhoods>(*atlas);
            m_neighbourhoodsOf = atlas;
        }
        // Changes per session step, as the artist's steps count: a run split into
        // substeps changes by 1/substeps as much per simulator step.
        LocalRegrowthOptions options;
        const float perStep = 1.0f / float(substeps());
        options.settledBelow *= perStep;
        options.spreadAbove *= perStep;
        m_regrowth.emplace(m_neighbourhoods, segmentSession().domain().sharedAtlas(), touched,
                           options);
    }
    m_simulator->setActiveTiles(m_regrowth->over() ? std::vector<int>{} : m_regrowth->tiles());
    if (m_regrowth->over())
        m_regrowth.reset();
}

void SessionRun::afterRegrowthSteps(int steps) {
    if (!m_regrowth->stepped(steps, [this] { return m_simulator->state(); }))
        return;
    if (m_regrowth->over())
        endRegrowth();
    else
        m_simulator->setActiveTiles(m_regrowth->tiles());
}

void SessionRun::endRegrowth() {
    if (!m_regrowth)
        return;
    m_regrowth.reset();
    m_simulator->setActiveTiles({});
}

Brush SessionRun::strokeWrite(const StrokeSpec& stroke) {
    const Session& part = segmentSession();
    Brush brush =
        strokeBrush(stroke, part.reactionModel(), part.domain(), part.atlasPositions.get());
    if (writesChemical(stroke.mode)) {
        if (!stroke.continues)
            m_strokeCoverage.clear();
        brush.region =
            uncoveredPart(brush.region, m_strokeCoverage[stroke.chemical], part.domain());
    }
    return brush;
}

void SessionRun::applyEdit(LiveEdit edit) {
    if (m_finished)
        throw InputError("the run has finished: there is nothing left to edit");
    edit.step = sessionStepsDone();
    // Checked before anything changes, so a refused edit leaves the run as it was.
    if (edit.stroke) {
        const Session& part = segmentSession();
        (void)strokeBrush(*edit.stroke, part.reactionModel(), part.domain(),
                          part.atlasPositions.get());
    }
    if (edit.dt && (!(*edit.dt > 0) || !std::isfinite(*edit.dt)))
        throw InputError("dt " + std::to_string(*edit.dt) + " is not a positive time step");
    applyNow(edit);
    m_applied.push_back(std::move(edit));
}

void SessionRun::takeSurface(Session& session, const Session& from) {
    if (session.surfaceGeometry == from.surfaceGeometry)
        return;
    useAtlas(session, from.atlas, from.atlasWeights);
    session.atlasPositions = from.atlasPositions;
    session.surfaceGeometry = from.surfaceGeometry;
}

void SessionRun::rebuildSegment() {
    // The current segment's session as entered (on its current surface), then
    // every edit made in it but the chemical strokes (the state holds those)
    // and the deformations (the surface holds those): parameters, dt, painted
    // maps and held cells come back as they were made, in order (a map painted
    // before a parameter change starts from the old value).
    m_simulator.reset();
    m_simulator = m_make(m_segments[m_index].session);
    m_simulator->setFrozen(m_frozen);
    const long long start = segmentStartStep();
    for (const LiveEdit& e : m_applied) {
        if (e.step < start)
            continue;
        LiveEdit replay = e;
        if (replay.stroke && writesChemical(replay.stroke->mode))
            replay.stroke.reset();
        replay.deform.reset();
        applyNow(replay, false);
    }
}

DeformedSurface SessionRun::deformSurface(const DeformSpec& spec) const {
    const Segment& segment = m_segments[m_index];
    const Session& part = segment.session;
    if (!part.surfaceGeometry)
        throw InputError("a deformation needs a session on a mesh (a \"surface\" block)");
    DeformedSurface d = part.surfaceGeometry->deformed(spec);
    // The segment keeps its substeps (its steps are counted in them): a
    // compression that needs more would blow the explicit step up.
    if (part.integrator == Integrator::ExplicitEuler && d.weights) {
        Session deformed = part;
        useAtlas(deformed, part.atlas, d.weights);
        int needed = atlasSubsteps(deformed);
        // A few texels squeezed a little past what the run's substeps hold
        // (the shear where a local stretch fades, say) take the weights'
        // floor: their area counts as larger, so their sums fit, the flux of
        // every pair kept. Isotropic weights only (the limit is their sum's);
        // a squeeze that would slow a texel's diffusion below half is refused.
        const double ratio = needed > segment.substeps && !d.weights->tensor && !d.weights->drift
                                 ? atlasSubstepRatio(deformed)
                                 : 0.0;
        if (ratio > 0) {
            const float limit =
                float(double(maxCoefficientSum(*d.weights)) * segment.substeps / ratio);
            float smallest = 1;
            auto capped = std::make_shared<const AtlasWeights>(
                capCoefficientSums(*d.weights, limit, nullptr, &smallest));
            useAtlas(deformed, part.atlas, capped);
            if (smallest >= 0.5f && atlasSubsteps(deformed) <= segment.substeps) {
                d.weights = capped;
                needed = segment.substeps;
            }
        }
        if (needed > segment.substeps)
            throw InputError(
                "deformation: " + std::string(spec.factor < 1 ? "compressing" : "stretching") +
                " by " + std::to_string(spec.factor) +
                " squeezes texels there (compressed, or sheared where a local stretch fades) "
                "so that a step needs " +
                std::to_string(needed) + " substeps and the run takes " +
                std::to_string(segment.substeps) +
                ": use a factor nearer 1 or a wider brush (slab)");
    }
    return d;
}

void SessionRun::useDeformedSurface(const DeformedSurface& d) {
    const State state = m_simulator->state();
    Session& session = m_segments[m_index].session;
    session = m_entry.session;
    useAtlas(session, session.atlas, d.weights);
    session.atlasPositions = d.positions;
    session.surfaceGeometry = d.geometry;
    rebuildSegment();
    m_simulator->setState(state);
    if (m_regrowth)
        m_simulator->setActiveTiles(m_regrowth->tiles());
}

RunCheckpoint SessionRun::checkpoint() const {
    RunCheckpoint c;
    c.index = m_index;
    c.stepsRun = m_stepsRun;
    c.stepsDone = m_stepsDone;
    c.finished = m_finished;
    c.segments = m_segments;
    c.entry = m_entry;
    c.frozen = m_frozen;
    c.state = state();
    c.applied = m_applied;
    c.nextEdit = m_nextEdit;
    c.stateModel = m_stateModel;
    c.strokeCoverage = m_strokeCoverage;
    c.regrowth = m_regrowth;
    return c;
}

void SessionRun::restore(const RunCheckpoint& c) {
    assert(c.segments.size() == m_segments.size());
    m_index = c.index;
    m_stepsRun = c.stepsRun;
    m_stepsDone = c.stepsDone;
    m_segments = c.segments;
    m_entry = c.entry;
    m_frozen = c.frozen;
    m_stateModel = c.stateModel;
    m_nextEdit = c.nextEdit;
    m_applied = c.applied;
    m_settledEarly = false;
    m_simulator.reset();
    if (c.finished) {
        m_finished = true;
        m_state = c.state;
        return;
    }
    m_finished = false;
    m_state = State();
    // The segment as entered, on the surface as it was then (deformed).
    m_segments[m_index] = m_entry;
    takeSurface(m_segments[m_index].session, c.segments[m_index].session);
    rebuildSegment();
    // What later levels had taken from live changes.
    for (std::size_t i = m_index + 1; i < m_segments.size(); ++i)
        m_segments[i] = c.segments[i];
    m_simulator->setState(c.state);
    m_strokeCoverage = c.strokeCoverage;
    m_regrowth = c.regrowth;
    if (m_regrowth)
        m_simulator->setActiveTiles(m_regrowth->tiles());
}

void SessionRun::endSegment() {
    if (!m_finished)
        finishSegment(m_simulator->takeState());
}

RunPosition SessionRun::position() const {
    RunPosition p;
    p.segment = int(m_index);
    p.segments = int(m_segments.size());
    p.segmentStep = m_stepsRun[m_index];
    p.segmentSteps = m_segments[m_index].session.steps;
    p.stepsDone = m_stepsDone;
    p.totalSteps = m_totalSteps;
    p.stages = !m_session.stages.empty();
    p.finished = m_finished;
    return p;
}

State SessionRun::state() const {
    return m_finished ? m_state : m_simulator->state();
}

Session SessionRun::completed() const {
    // What reproduces this state: the session's own segments with the steps
    // they ran, in session steps. Refinement levels are not the session's:
    // every run of it plans them again.
    Session done = m_session;
    std::size_t own = 0;
    while (own < m_segments.size() && !m_segments[own].refine)
        ++own;
    const std::size_t entered = std::min(m_stepsRun.size(), own);
    auto sessionSteps = [&](std::size_t i) { return m_stepsRun[i] / m_segments[i].substeps; };
    done.steps = 0;
    for (std::size_t i = 0; i < entered; ++i)
        done.steps += sessionSteps(i);
    if (!m_session.schedule.empty()) {
        done.schedule.resize(entered);
        for (std::size_t i = 0; i < entered; ++i)
            done.schedule[i].steps = sessionSteps(i);
        if (done.schedule.back().width != m_session.width ||
            done.schedule.back().height != m_session.height)
            done.schedule.push_back({m_session.width, m_session.height, 0});
    }
    if (!m_session.stages.empty()) {
        done.stages.resize(entered);
        for (std::size_t i = 0; i < entered; ++i) {
            done.stages[i].steps = sessionSteps(i);
            // Live changes: a value in force that differs from what the stage
            // would inherit is written into it.
            const Session& part = m_segments[i].session;
            ParamValues inherited = i == 0 ? m_session.params : m_segments[i - 1].session.params;
            float inheritedDt = i == 0 ? m_session.dt : m_segments[i - 1].sessionDt;
            if (m_segments[i].newModel) {
                inherited.clear();
                for (const ParamSpec& p : part.reactionModel().params())
                    inherited[p.name] = p.defaultValue;
                inheritedDt = part.reactionModel().defaultDt();
            }
            if (m_segments[i].sessionDt != inheritedDt || done.stages[i].dt)
                done.stages[i].dt = m_segments[i].sessionDt;
            for (const auto& [name, value] : part.params) {
                auto it = inherited.find(name);
                if (it == inherited.end() || it->second != value ||
                    done.stages[i].params.count(name))
                    done.stages[i].params[name] = value;
            }
        }
    } else {
        // Levels share their parameters and dt (setParams/setDt change the
        // current level and those after it).
        done.params = segmentSession().params;
        done.dt = m_segments[m_index].sessionDt;
    }
    // With edits, they are the record of live changes: the session starts
    // from its own values and replays them (a change by setParams outside an
    // edit is not recorded then).
    // A cascade stopped before the stage that switches to the model its
    // colour map names: the written session must still read back, showing
    // the model it ends with.
    if (!done.colormap.chemical.empty() &&
        done.outputModel().chemicalIndex(done.colormap.chemical) < 0)
        done.colormap.chemical.clear();
    done.edits = m_applied;
    if (!m_applied.empty()) {
        done.params = m_session.params;
        done.dt = m_session.dt;
        for (std::size_t i = 0; i < done.stages.size(); ++i) {
            done.stages[i].params = m_session.stages[i].params;
            done.stages[i].dt = m_session.stages[i].dt;
        }
    }
    return done;
}

RunResult SessionRun::result() const {
    return resultWith(state());
}

RunResult SessionRun::takeResult() {
    return resultWith(m_finished ? std::exchange(m_state, State()) : m_simulator->state());
}

RunResult SessionRun::resultWith(State state) const {
    RunResult r;
    r.stepsDone = m_stepsDone;
    r.state = std::move(state);
    // A run stopped on a coarse level leaves a coarse state: bring it to the final size.
    if (r.state.width() != m_session.width || r.state.height() != m_session.height)
        r.state = resampleBilinear(r.state, m_session.width, m_session.height, m_session.edges);
    r.completed = completed();
    return r;
}

void SessionRun::setParams(const ParamValues& params) {
    if (m_finished)
        return;
    Session& part = m_segments[m_index].session;
    const ReactionModel& model = part.reactionModel();
    for (const auto& [name, value] : params) {
        const ParamSpec* p = model.param(name);
        if (!p)
            throw InputError("parameter '" + name + "' is not a parameter of model '" +
                             model.name() + "' (accepted: " + model.paramNames() + ")" +
                             didYouMean(name, splitNameList(model.paramNames())));
        if (!std::isfinite(value) || value < p->min || value > p->max) {
            std::ostringstream os;
            os << "parameter " << name << " = " << value << " is outside [" << p->min << ", "
               << p->max << "]";
            throw InputError(os.str());
        }
    }
    ParamValues merged = part.params;
    for (const auto& [name, value] : params)
        merged[name] = value;
    m_simulator->setParams(merged);
    part.params = merged;
    // Later levels (and refinement, which continues the last stage) take it.
    for (std::size_t i = m_index + 1; i < m_segments.size(); ++i)
        if (m_session.stages.empty() || m_segments[i].refine)
            m_segments[i].session.params = merged;
}

void SessionRun::setDt(float dt) {
    if (!(dt > 0) || !std::isfinite(dt)) {
        std::ostringstream os;
        os << "dt " << dt << " is not a positive time step";
        throw InputError(os.str());
    }
    if (m_finished)
        return;
    // `dt` is a session dt: a segment finer than one cell per unit takes
    // substeps of dt / substeps.
    m_simulator->setDt(dt / float(m_segments[m_index].substeps));
    for (std::size_t i = m_index; i < m_segments.size(); ++i)
        if (i == m_index || m_session.stages.empty() || m_segments[i].refine) {
            m_segments[i].sessionDt = dt;
            m_segments[i].session.dt = dt / float(m_segments[i].substeps);
        }
}

void SessionRun::replaceSession(const Session& session) {
    if (m_finished)
        return;
    Segment& segment = m_segments[m_index];
    const ReactionModel& now = segment.session.reactionModel();
    const ReactionModel& next = session.reactionModel();
    if (session.width != segment.session.width || session.height != segment.session.height)
        throw InputError("the replacement session is " + std::to_string(session.width) + " x " +
                         std::to_string(session.height) + "; the run's grid is " +
                         std::to_string(segment.session.width) + " x " +
                         std::to_string(segment.session.height));
    if (next.chemicalNames() != now.chemicalNames())
        throw InputError("model '" + next.name() + "' has chemicals " + next.chemicalNames() +
                         "; the run's state holds " + now.chemicalNames());
    Session part = session;
    part.steps = segment.session.steps;
    part.gridSpacing = segment.session.gridSpacing;
    part.schedule.clear();
    part.stages.clear();
    // The new simulator is built before the old one goes, so a refused
    // session (InputError) leaves the run as it was.
    const State state = m_simulator->state();
    std::unique_ptr<Simulator> simulator = m_make(part);
    simulator->setState(state);
    simulator->setFrozen(m_frozen);
    m_simulator = std::move(simulator);
    segment.session = part;
    m_stateModel = &next;
    m_regrowth.reset(); // the new simulator steps every tile
}

} // namespace morphogen
