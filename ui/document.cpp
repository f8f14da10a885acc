#include "ui/document.hpp"

#include <algorithm>
#include <cassert>
#include <climits>
#include <utility>

#include "core/base/errors.hpp"
#include "core/base/limits.hpp"
#include "core/output/colormap.hpp"
#include "core/sim/segments.hpp"

namespace morphogen::ui {

Session openEnded(Session s) {
    s.coarseToFine = false;
    if (!s.schedule.empty()) {
        // The canvas is one size: the levels' steps run at the final size.
        s.schedule.clear();
    }
    // A run takes at most INT_MAX engine steps: on a model each session step
    // may take many substeps (small texels, drops' drift), so it runs fewer.
    const long long most =
        s.atlasWeights ? std::min<long long>(kMaxSteps, INT_MAX / atlasSubsteps(s)) : kMaxSteps;
    const long long extra = most / 2;
    if (s.stages.empty()) {
        s.steps = int(most);
    } else {
        s.stages.back().steps = int(std::min<long long>(s.stages.back().steps + extra, most));
        long long total = 0;
        for (const Stage& stage : s.stages)
            total += stage.steps;
        s.steps = int(std::min<long long>(total, most));
    }
    return s;
}

Document::Document(SimulatorFactory makeSimulator) : m_make(std::move(makeSimulator)) {}

std::unique_ptr<SessionRun> Document::startRun(const Session& base) const {
    // No blow-up checks inside advance: the designer checks each frame's
    // result itself (a check reads the whole state back).
    return std::make_unique<SessionRun>(openEnded(base), m_make, 0);
}

void Document::swapSession(Session base, std::unique_ptr<SessionRun> run, std::string path,
                           const std::string& label) {
    if (m_run) {
        // The old session and run wait in the undo step (a GPU run keeps its
        // textures: kMaxUndo bounds how many).
        auto old = std::make_shared<std::pair<Session, std::unique_ptr<SessionRun>>>(
            std::move(m_base), std::move(m_run));
        auto oldPath = std::make_shared<std::string>(m_path);
        auto swap = [this, old, oldPath] {
            std::swap(m_base, old->first);
            std::swap(m_run, old->second);
            std::swap(m_path, *oldPath);
            m_history.clear();
            changed();
        };
        m_base = std::move(base);
        m_run = std::move(run);
        m_path = std::move(path);
        push({label, swap, swap});
    } else {
        m_base = std::move(base);
        m_run = std::move(run);
        m_path = std::move(path);
    }
    m_history.clear();
    changed();
}

void Document::open(Session session, const std::string& path) {
    std::unique_ptr<SessionRun> run = startRun(session); // throws before anything changes
    const bool first = !m_run;
    swapSession(std::move(session), std::move(run), path, "open " + session.name);
    m_dirty = false;
    if (first) {
        m_undo.clear();
        m_redo.clear();
    }
}

int Document::advance(int sessionSteps) {
    assert(m_run);
    const int n = m_run->advance(sessionSteps * m_run->substeps());
    if (n > 0)
        m_dirty = true; // the pattern grew: unsaved, but the settings are as they were
    return n;
}

void Document::reset() {
    replace(m_base, "reset");
}

void Document::reseed(std::uint64_t seed) {
    Session s = m_base;
    s.seed = seed;
    replace(std::move(s), "reseed");
}

void Document::replace(Session session, const std::string& label) {
    std::unique_ptr<SessionRun> run = startRun(session);
    swapSession(std::move(session), std::move(run), m_path, label);
    changed();
}

void Document::setColormap(const ColorMapSpec& colormap) {
    const ColorMapSpec before = m_base.colormap;
    auto set = [this](const ColorMapSpec& c) {
        m_base.colormap = c;
        m_run->setColormap(c);
        changed();
    };
    set(colormap);
    push({"colour map " + colormap.name, [set, before] { set(before); },
          [set, colormap] { set(colormap); }});
}

void Document::beginChange(const std::string& label) {
    assert(m_run && !m_change);
    m_change = OpenChange{label, live().params, m_run->segmentSession().dt * m_run->substeps()};
}

void Document::setParam(const std::string& name, float value) {
    LiveEdit e;
    e.params[name] = value;
    m_run->applyEdit(std::move(e));
    changed();
}

void Document::setDt(float dt) {
    LiveEdit e;
    e.dt = dt;
    m_run->applyEdit(std::move(e));
    changed();
}

void Document::changeOnce(const std::string& label, const std::function<void()>& apply) {
    beginChange(label);
    try {
        apply();
    } catch (...) {
        endChange();
        throw;
    }
    endChange();
}

void Document::endChange() {
    if (!m_change)
        return;
    const OpenChange before = std::move(*m_change);
    m_change.reset();
    const ParamValues after = live().params;
    const float afterDt = m_run->segmentSession().dt * m_run->substeps();
    if (after == before.params && afterDt == before.dt)
        return;
    // Undo is another live edit (the pattern grown since stays): parameters
    // are settings, not paint.
    auto apply = [this](const ParamValues& params, float dt) {
        LiveEdit e;
        e.params = params;
        e.dt = dt;
        m_run->applyEdit(std::move(e));
        changed();
    };
    push({before.label, [apply, before] { apply(before.params, before.dt); },
          [apply, after, afterDt] { apply(after, afterDt); }});
}

void Document::beginStroke(const StrokeSpec& brush, const std::optional<StrokeSpec>& companion) {
    assert(m_run && !m_stroke);
    m_stroke = OpenStroke{brush, companion, m_run->checkpoint(), {}, std::nullopt, std::nullopt};
}

void Document::extendStroke(const std::vector<std::array<double, 2>>& points) {
    if (!m_stroke || points.empty() || m_stroke->brush.surface)
        return;
    StrokeSpec piece = m_stroke->brush;
    piece.points.clear();
    // Each piece starts where the last one ended, so the swept line has no gaps.
    if (m_stroke->last)
        piece.points.push_back(*m_stroke->last);
    piece.points.insert(piece.points.end(), points.begin(), points.end());
    applyPiece(std::move(piece));
    m_stroke->last = points.back();
}

void Document::extendSurfaceStroke(const std::vector<std::array<double, 3>>& points) {
    if (!m_stroke || points.empty() || !m_stroke->brush.surface)
        return;
    StrokeSpec piece = m_stroke->brush;
    piece.surface = true;
    piece.points.clear();
    piece.surfacePoints.clear();
    if (m_stroke->lastOnSurface)
        piece.surfacePoints.push_back(*m_stroke->lastOnSurface);
    piece.surfacePoints.insert(piece.surfacePoints.end(), points.begin(), points.end());
    applyPiece(std::move(piece));
    m_stroke->lastOnSurface = points.back();
}

void Document::applyPiece(StrokeSpec piece) {
    // Randomise: each piece draws its own noise.
    piece.seed = m_stroke->brush.seed + m_stroke->pieces.size();
    piece.continues = !m_stroke->pieces.empty();
    std::vector<StrokeSpec> edits = {piece};
    if (m_stroke->companion) {
        StrokeSpec with = piece;
        with.mode = m_stroke->companion->mode;
        with.chemical = m_stroke->companion->chemical;
        with.param = m_stroke->companion->param;
        with.value = m_stroke->companion->value;
        with.continues = true; // the first piece's own coverage starts here
        edits.push_back(std::move(with));
    }
    for (StrokeSpec& e : edits) {
        LiveEdit edit;
        edit.stroke = e;
        m_run->applyEdit(std::move(edit));
        m_stroke->pieces.push_back(std::move(e));
    }
    changed();
}

void Document::endStroke() {
    if (!m_stroke)
        return;
    OpenStroke stroke = std::move(*m_stroke);
    m_stroke.reset();
    if (stroke.pieces.empty())
        return;
    auto before = std::make_shared<RunCheckpoint>(std::move(stroke.before));
    auto pieces = std::make_shared<std::vector<StrokeSpec>>(std::move(stroke.pieces));
    // Undo goes back to the moment before the stroke, state and all: the
    // steps run since are undone with it.
    auto undo = [this, before] {
        m_run->restore(*before);
        changed();
    };
    auto redo = [this, pieces] {
        for (const StrokeSpec& piece : *pieces) {
            LiveEdit e;
            e.stroke = piece;
            m_run->applyEdit(std::move(e));
        }
        changed();
    };
    push({toString(pieces->front().mode) + " stroke", undo, redo});
}

void Document::push(Action action) {
    m_undo.push_back(std::move(action));
    if (m_undo.size() > kMaxUndo)
        m_undo.erase(m_undo.begin());
    m_redo.clear();
}

void Document::undo() {
    if (m_undo.empty())
        return;
    Action a = std::move(m_undo.back());
    m_undo.pop_back();
    a.undo();
    changed();
    m_redo.push_back(std::move(a));
    // A restored checkpoint forgets later edits; snapshots past it no longer
    // belong to this run.
    m_history.dropAfterStep(steps());
}

void Document::redo() {
    if (m_redo.empty())
        return;
    Action a = std::move(m_redo.back());
    m_redo.pop_back();
    a.redo();
    changed();
    m_undo.push_back(std::move(a));
}

ColorMapSpec Document::liveColormap() const {
    ColorMapSpec spec = live().colormap;
    if (!spec.chemical.empty() && live().reactionModel().chemicalIndex(spec.chemical) < 0)
        spec.chemical.clear();
    return spec;
}

int Document::liveChemical() const {
    return colormapChemical(liveColormap(), live().reactionModel());
}

Session Document::completed() const {
    Session s = m_run->completed();
    s.name = m_base.name;
    s.description = m_base.description;
    return s;
}

void Document::save(const std::string& path) {
    saveSessionFile(completed(), path);
    m_path = path;
    m_dirty = false;
}

void Document::deform(const DeformSpec& spec) {
    assert(m_run && !m_stroke);
    auto before = std::make_shared<RunCheckpoint>(m_run->checkpoint());
    auto apply = [this, spec] {
        LiveEdit e;
        e.deform = spec;
        m_run->applyEdit(std::move(e));
        changed();
    };
    apply();
    // Undo returns to the moment before, surface and state; redo deforms
    // again where the run is then (as a stroke's redo paints again).
    push({"deform",
          [this, before] {
              m_run->restore(*before);
              changed();
          },
          apply});
}

void Document::recordSnapshot() {
    if (!m_history.empty() && m_history.lastStep() >= steps())
        return;
    m_history.record(steps(), m_run->checkpoint());
}

void Document::branch(std::size_t index) {
    assert(index < m_history.size());
    auto before = std::make_shared<RunCheckpoint>(m_run->checkpoint());
    auto target = std::make_shared<RunCheckpoint>(m_history.checkpoint(index));
    m_run->restore(*target);
    m_history.keepUpTo(index);
    changed();
    // Undo returns to where the run was, edits and all.
    push({"go back to step " + std::to_string(m_history.step(index)),
          [this, before] { m_run->restore(*before); },
          [this, target] { m_run->restore(*target); }});
}

} // namespace morphogen::ui
