#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/session/session.hpp"
#include "core/sim/session_run.hpp"
#include "ui/growth_history.hpp"

namespace morphogen::ui {

// The designer's open session and its live run, with undo and a growth
// history. GL-free: the simulators come from a factory (the window's GPU
// backend, or the CPU one), so tests drive it headless.
//
// The canvas runs a session open-ended: its last stage (or its one level)
// goes on past its steps until the artist stops, at the session's size (no
// coarse-to-fine: the canvas is one size). Every change made while it runs
// is a live edit of the engine (SessionRun::applyEdit), so save() writes a
// session that `morphogen render` reproduces, and undo goes back through
// checkpoints of the same run.
class Document {
public:
    explicit Document(SimulatorFactory makeSimulator);

    // Opens `session` (a preset or a session file; `path` empty for a
    // preset). Throws InputError for a session the engine refuses; the open
    // document is then unchanged. Undoable.
    void open(Session session, const std::string& path = "");
    bool isOpen() const { return m_run != nullptr; }

    // The session as opened (parameters and dt as they started).
    const Session& session() const { return m_base; }
    const std::string& path() const { return m_path; }
    // The session the current segment runs, live values included.
    const Session& live() const { return m_run->segmentSession(); }
    // live()'s colour map for what the current segment holds: a cascade's
    // map may name a chemical of a later stage's model, shown from then on;
    // before, the segment's model's display chemical.
    ColorMapSpec liveColormap() const;
    int liveChemical() const;
    SessionRun& run() { return *m_run; }
    const SessionRun& run() const { return *m_run; }

    // Advances up to `sessionSteps` session steps; returns how many ran.
    // Throws BlowUpError as SessionRun does (the run then stays where it
    // stopped; undo goes back before the change that blew it up).
    int advance(int sessionSteps);
    long long steps() const { return m_run->sessionStepsDone(); }

    // Back to the start of the session (or with a new seed): undoable.
    void reset();
    void reseed(std::uint64_t seed);
    // Replaces the session's setup (operator, integrator, size, edges,
    // colour map): the run starts again from it. Undoable.
    void replace(Session session, const std::string& label);

    // The colour map (no restart: it changes the picture, not the run). Undoable.
    void setColormap(const ColorMapSpec& colormap);

    // Parameters and dt, applied now as live edits. A slider drag calls
    // beginChange once, then setParam every frame, then endChange: one undo
    // step for the drag.
    void beginChange(const std::string& label);
    void setParam(const std::string& name, float value);
    void setDt(float dt);
    void endChange();
    // A typed value or a click: beginChange, `apply` (setParam, setDt), then
    // endChange, also when `apply` throws (which it rethrows).
    void changeOnce(const std::string& label, const std::function<void()>& apply);

    // A brush stroke: begin, extend by the points the cursor crossed since
    // the last call (each extension is one brush write on the cells it
    // covers), end. One undo step for the stroke. A companion stroke (a
    // watercolour brush's pigment, laid with its water) follows the same
    // path, piece by piece, as its own edit.
    void beginStroke(const StrokeSpec& brush,
                     const std::optional<StrokeSpec>& companion = std::nullopt);
    void extendStroke(const std::vector<std::array<double, 2>>& points);
    // The same on a session's mesh: points on the surface, for a stroke begun
    // with a surface brush (each kind of stroke takes only its own points).
    void extendSurfaceStroke(const std::vector<std::array<double, 3>>& points);
    void endStroke();
    bool stroking() const { return m_stroke.has_value(); }

    bool canUndo() const { return !m_undo.empty(); }
    bool canRedo() const { return !m_redo.empty(); }
    std::string undoLabel() const { return canUndo() ? m_undo.back().label : ""; }
    std::string redoLabel() const { return canRedo() ? m_redo.back().label : ""; }
    void undo();
    void redo();

    // The session that reproduces the canvas now (the steps run, every edit).
    Session completed() const;
    // Writes completed() to `path` (atomically) and remembers the path.
    void save(const std::string& path);
    // Changes since the last open or save.
    bool dirty() const { return m_dirty; }
    // Counts changes of the settings (parameters, dt, colour map, session,
    // undo, redo), not steps: views derived from the settings (the stability
    // report) recompute only when it moves.
    std::uint64_t revision() const { return m_revision; }

    // Deforms the model's surface (a live edit, LiveEdit::deform): the
    // pattern re-grows there. Undoable; throws InputError (nothing changed)
    // for a deformation the engine refuses.
    void deform(const DeformSpec& spec);

    // Growth history: checkpoints taken as the pattern grows (growth_history.hpp:
    // a memory budget, then a spill folder on disk, then thinning). Scrubbing
    // shows one; branch() continues from it (the run forgets what came after
    // it: undoable).
    void recordSnapshot();
    const GrowthHistory& history() const { return m_history; }
    void setHistoryBudget(std::size_t budgetBytes) { m_history.setMemoryBudget(budgetBytes); }
    void setHistorySpill(const std::string& folder, std::size_t diskBudget) {
        m_history.setSpill(folder, diskBudget);
    }
    void branch(std::size_t index);

    // Undo steps kept; older ones are dropped (each may hold a state copy).
    static constexpr std::size_t kMaxUndo = 64;

private:
    struct Action {
        std::string label;
        std::function<void()> undo, redo;
    };
    void push(Action action);
    // Makes the run of m_base from its start.
    std::unique_ptr<SessionRun> startRun(const Session& base) const;
    // Swaps in another session and run (open, reset, replace): undo swaps back.
    void swapSession(Session base, std::unique_ptr<SessionRun> run, std::string path,
                     const std::string& label);

    SimulatorFactory m_make;
    Session m_base;
    std::string m_path;
    std::unique_ptr<SessionRun> m_run;
    std::vector<Action> m_undo, m_redo;
    bool m_dirty = false;
    std::uint64_t m_revision = 0;
    void changed() {
        m_dirty = true;
        ++m_revision;
    }

    struct OpenChange {
        std::string label;
        ParamValues params;
        float dt;
    };
    std::optional<OpenChange> m_change;
    struct OpenStroke {
        StrokeSpec brush;
        std::optional<StrokeSpec> companion; // laid along the same path (watercolour pigment)
        RunCheckpoint before;
        std::vector<StrokeSpec> pieces; // as applied: what redo applies again
        std::optional<std::array<double, 2>> last;
        std::optional<std::array<double, 3>> lastOnSurface;
    };
    void applyPiece(StrokeSpec piece);
    std::optional<OpenStroke> m_stroke;

    GrowthHistory m_history;
};

// The session as the canvas runs it: at its size without coarse-to-fine,
// its last stage or level continuing for up to kMaxSteps; its edits stay
// (a saved designer session replays its strokes on the way to its steps).
Session openEnded(Session session);

} // namespace morphogen::ui
