#pragma once

#include <string>

#include <nlohmann/json_fwd.hpp>

namespace morphogen::bench {

// What the designer rows of `morphogen bench` run.
struct DesignerBench {
    std::string preset; // a single-stage preset (gs_coral)
    int size = 512;
    double seconds = 1; // the baseline's measurement; a designer run is 150 frames or more
};

// The designer rows: the CPU backend's it/s on the preset at size x size
// (the baseline, measured here as the throughput rows measure it, before and
// after every designer run), then `morphogen design` in a child process on
// the same session (one cell per length unit, so a session step is a
// simulator step) driven by a script: three runs at the steps per frame that
// 80% of the baseline needs at 30 frames/s, then one in the auto mode. Each
// row: frames/s, steps/s and steps/s over the mean of the baselines around
// it; then how many runs met the goal (0.8 or more at 30 frames/s or
// more) and the median. Needs a display ($DISPLAY: xvfb-run on a headless
// machine); without one the rows are skipped with a note. Returns
// {"runs": [rows], "goal": {...}} ("skipped" instead of "goal" without a
// display).
nlohmann::json benchDesigner(const DesignerBench& bench);

} // namespace morphogen::bench
