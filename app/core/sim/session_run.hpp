#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/sim/local_regrowth.hpp"
#include "core/sim/runner.hpp"
#include "core/sim/segments.hpp"
#include "core/sim/stroke_brush.hpp"

namespace morphogen {

// Where a SessionRun is. At a boundary it reports the next segment at step 0
// (that segment's freeze, reset or model change already applied).
struct RunPosition {
    int segment = 0;       // stage or level index
    int segments = 1;      // how many the session has
    int segmentStep = 0;   // steps done in the current segment
    int segmentSteps = 0;  // the current segment's length
    int stepsDone = 0;     // over all segments
    int totalSteps = 0;    // over all segments
    bool stages = false;   // the segments are cascade stages (else schedule levels)
    bool finished = false; // every segment has run all its steps
};

// A run's position and everything needed to go back to it
// (SessionRun::checkpoint/restore): the designer's undo and growth history.
// It holds a copy of the state.
struct RunCheckpoint {
    std::size_t index = 0;
    std::vector<int> stepsRun;
    int stepsDone = 0;
    bool finished = false;
    std::vector<Segment> segments; // as at the checkpoint (later levels' live values)
    Segment entry;                 // the current segment as it was entered
    std::vector<std::uint8_t> frozen;
    State state;
    std::vector<LiveEdit> applied; // the edits applied until then
    std::size_t nextEdit = 0;      // the session's own edits still to come
    const ReactionModel* stateModel = nullptr;
    StrokeCoverages strokeCoverage;
    std::optional<LocalRegrowth> regrowth;
};

// A session advanced step by step: cascade stages and schedule levels are
// positions in it, so a batch render, the bench and an interactive frame loop
// run the same code with the same results. Between advances a caller may read
// the position, change parameters or dt live (setParams/setDt: no rebuild),
// swap in an edited session (replaceSession: a rebuild that keeps the state),
// stop and resume. The state stays in the simulator; state() reads it back.
class SessionRun {
public:
    // Enters the first segment: its simulator is made and holds the initial
    // state. checkEvery: steps between blow-up checks, counted from each
    // segment's start as runSimulation's chunks (a check reads the state
    // back); 0 checks only at segment ends.
    SessionRun(const Session& session, SimulatorFactory makeSimulator, int checkEvery = 250);

    // Runs up to `steps` steps (fewer when the session ends), across segment
    // boundaries; returns the steps run. Throws BlowUpError as runSimulation
    // does, naming the stage or level when there are several.
    int advance(int steps);
    // Ends the current segment now (its steps so far are what it ran) and
    // enters the next; at the last one, the run is finished.
    void endSegment();

    bool finished() const { return m_finished; }

    // Ends the session's last own segment (its last stage or level, before
    // any refinement) early when `settled` says so: it is asked with the
    // state every `every` session steps of that segment, from `after` session
    // steps on. The segment's steps are then the cap. every 0: off.
    void setSettleCheck(int every, int after, std::function<bool(const State&)> settled);
    // Whether the settle check ended the segment.
    bool settledEarly() const { return m_settledEarly; }
    RunPosition position() const;
    // Steps left in the current segment.
    int segmentRemaining() const;

    // The current segment's simulator (for live changes and display) and the
    // session it runs as. A finished run has released its simulator (only
    // the final state is held): simulator() is for runs not finished.
    Simulator& simulator() { return *m_simulator; }
    const Session& segmentSession() const { return m_segments[m_index].session; }

    // Reads the current state back (at the current segment's size).
    State state() const;
    // The session that reproduces the steps run so far (each stage or level
    // with the steps it ran). Live parameter and dt changes are recorded as
    // the values in force at the end of each stage (of the current level for a
    // schedule), not as the moment they happened; a replaceSession's other
    // changes (operator, model) are not recorded.
    Session completed() const;
    // completed() and the state, resampled to the session's final size when a
    // run stopped on a coarse level.
    RunResult result() const;
    // result(), the final state moved out rather than copied (a big render
    // holds one copy at the end): the run is spent, state() is empty after.
    RunResult takeResult();

    // Live changes to the current segment, from the next step on: the
    // simulator updates its constants (uniforms on the GPU, no rebuild).
    // Parameters missing from `params` keep their values; unknown names or
    // values outside a parameter's range throw InputError. Schedule levels
    // after the current one take the change too; later cascade stages do not
    // (each runs as its session says).
    void setParams(const ParamValues& params);
    void setDt(float dt);

    // Rebuilds the current segment's simulator for `session` (an operator or
    // model change) and carries the state over, with the frozen cells. The
    // session must have the segment's size and a model with the same
    // chemicals; its steps are ignored (the segment keeps its length).
    void replaceSession(const Session& session);

    // The colour map of the session and every segment: it changes no step,
    // only how the result is shown and what completed() records.
    void setColormap(const ColorMapSpec& colormap);

    // Session steps run so far over every segment (position() counts
    // simulator steps, which are substeps on a grid finer than one cell per
    // unit): the clock of live edits.
    long long sessionStepsDone() const;
    // The current segment's simulator steps per session step: advance by
    // multiples of it to stay on session steps, where edits are recorded.
    int substeps() const { return m_segments[m_index].substeps; }

    // Applies a live edit now (parameters, dt, then the stroke) and records
    // it at sessionStepsDone(), so that completed() reproduces it. Throws
    // InputError for an edit the current model refuses, leaving the run as
    // it was; or when the run has finished.
    void applyEdit(LiveEdit edit);
    // The edits applied so far, the session's own and applyEdit's, in order.
    const std::vector<LiveEdit>& edits() const { return m_applied; }

    // The localized re-growth under way after a localized surface stroke
    // (StrokeSpec::localized): its active tiles and phase; null when every
    // tile steps. A parameter or dt change, a stroke that is not localized
    // and a new segment end it.
    const LocalRegrowth* regrowth() const { return m_regrowth ? &*m_regrowth : nullptr; }

    // The run as it is now, and a return to such a moment, earlier or later
    // (of the same run: a checkpoint of another SessionRun is a programmer
    // error). Restoring gives back the state bit for bit, the position, the
    // parameters and dt in force, the painted maps and held cells (replayed
    // from the edits) and the edit record as it was then.
    RunCheckpoint checkpoint() const;
    void restore(const RunCheckpoint& checkpoint);

private:
    void enterSegment(std::size_t index);
    // Reads the simulator's state in place (Simulator::insaneValue).
    void checkBlowUp(int before) const;
    bool inSettleSegment() const;
    void finishSegment(State state);
    // Applies the session's own edits that are due at sessionStepsDone().
    void applyDueEdits();
    // Applies an edit without recording it; `follow`: start, extend or end
    // the localized re-growth as the edit asks (not when restore replays
    // edits: the checkpoint holds the re-growth).
    void applyNow(const LiveEdit& edit, bool follow = true);
    void followEdit(const LiveEdit& edit, const Brush* written, const std::vector<int>& deformed);
    // Deformations (LiveEdit::deform): the deformed surface, refused
    // (InputError) before anything changes; then the segment rebuilt on it.
    DeformedSurface deformSurface(const DeformSpec& spec) const;
    void useDeformedSurface(const DeformedSurface& d);
    // The current segment's simulator made again from its session and the
    // edits made in it (restore, deformations).
    void rebuildSegment();
    static void takeSurface(Session& session, const Session& from);
    // Counts steps run under a re-growth and updates the active tiles.
    void afterRegrowthSteps(int steps);
    void endRegrowth();
    // The brush write of a stroke edit now (its uncovered part for a piece
    // that continues a stroke).
    Brush strokeWrite(const StrokeSpec& stroke);
    // Simulator steps of the current segment until the next own edit is due
    // (INT_MAX when none is due in it).
    int stepsToNextEdit() const;
    long long segmentStartStep() const; // session steps before the current segment
    RunResult resultWith(State state) const;

    Session m_session;
    SimulatorFactory m_make;
    int m_checkEvery;
    std::vector<Segment> m_segments;
    std::size_t m_index = 0;
    std::vector<int> m_stepsRun; // per segment entered
    int m_stepsDone = 0;
    int m_totalSteps = 0; // over all segments: position() is asked after every chunk
    bool m_finished = false;
    std::unique_ptr<Simulator> m_simulator; // null once finished
    // The state between segments and at the end; empty inside a segment,
    // where the simulator holds it (a big render keeps one copy, not two).
    State m_state;
    std::vector<std::uint8_t> m_frozen;
    const ReactionModel* m_stateModel = nullptr; // the model m_state holds
    int m_settleEvery = 0; // in steps of the settle segment (session steps x substeps)
    int m_settleAfter = 0;
    std::function<bool(const State&)> m_settled;
    bool m_settledEarly = false;
    Segment m_entry;            // the current segment as entered (restore starts from it)
    std::size_t m_nextEdit = 0; // into m_session.edits
    std::vector<LiveEdit> m_applied;
    StrokeCoverages m_strokeCoverage; // the last stroke's, for the pieces that continue it
    std::optional<LocalRegrowth> m_regrowth;
    std::shared_ptr<const TileNeighbourhoods> m_neighbourhoods; // of m_neighbourhoodsOf
    const Atlas* m_neighbourhoodsOf = nullptr;
};

} // namespace morphogen
