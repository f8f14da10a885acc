#include "test_support.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

#include "core/sim/cpu_simulator.hpp"

namespace morphogen::test {

Session smallSession(const std::string& preset, int size, int steps) {
    Session s = loadPreset(preset);
    s.width = s.height = size;
    s.length = 0; // one unit per cell: the preset's model on a small grid, not its pattern
    s.steps = steps;
    return s;
}

Session shrunk(Session s, int size, int stepsPerSegment) {
    s.width = s.height = size;
    s.length = 0; // one unit per cell (see smallSession)
    if (!s.schedule.empty()) {
        const int levels = int(s.schedule.size());
        for (int i = 0; i < levels; ++i) {
            const int side = std::max(4, size >> (levels - 1 - i));
            s.schedule[std::size_t(i)] = {side, side, stepsPerSegment};
        }
        s.steps = stepsPerSegment * levels;
    } else if (!s.stages.empty()) {
        for (Stage& stage : s.stages)
            stage.steps = stepsPerSegment;
        s.steps = stepsPerSegment * int(s.stages.size());
    } else {
        s.steps = stepsPerSegment;
    }
    return s;
}

float maxAbsValue(const State& s) {
    float worst = 0.0f;
    for (int c = 0; c < s.channels(); ++c)
        for (std::size_t i = 0; i < s.cellCount(); ++i)
            worst = std::max(worst, std::fabs(s.plane(c)[i]));
    return worst;
}

double planeSum(const State& s, int chemical) {
    double sum = 0;
    for (std::size_t i = 0; i < s.cellCount(); ++i)
        sum += s.plane(chemical)[i];
    return sum;
}

float maxAbsDifference(const State& a, const State& b) {
    float worst = 0.0f;
    for (int c = 0; c < a.channels(); ++c)
        for (std::size_t i = 0; i < a.cellCount(); ++i) {
            const float d = std::fabs(a.plane(c)[i] - b.plane(c)[i]);
            worst = std::isnan(d) ? INFINITY : std::max(worst, d);
        }
    return worst;
}

std::filesystem::path scratchDir(const std::string& name) {
    // One directory per process: ctest runs the same gl test on EGL and OSMesa at once, and
    // two processes writing one file made CI fail ("cannot move the file into place").
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / (name + "-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir;
}

std::filesystem::path freshScratchDir(const std::string& name, const std::string& sub) {
    const std::filesystem::path dir = scratchDir(name) / sub;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

std::string readTextFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

State runCpu(const Session& session) {
    CpuSimulator sim(session);
    sim.setState(makeInitialState(session.init, session.reactionModel(), session.params,
                                  session.width, session.height, session.seed));
    sim.run(session.steps);
    return sim.state();
}

} // namespace morphogen::test
