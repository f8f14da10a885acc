#pragma once

#include <filesystem>
#include <string>

#include "core/base/state.hpp"
#include "core/session/session.hpp"

namespace morphogen::test {

// A preset shrunk for tests: size x size cells, `steps` steps.
Session smallSession(const std::string& preset, int size, int steps);

// Any session (preset) cut down for a quick run: size x size cells and
// `stepsPerSegment` steps in each stage or schedule level (a schedule keeps
// its levels, halving the size per level below the last).
Session shrunk(Session session, int size, int stepsPerSegment);

// Largest absolute value over all chemicals (for tolerances relative to a
// model's range).
float maxAbsValue(const State& s);

// Largest absolute difference over all chemicals.
float maxAbsDifference(const State& a, const State& b);
// The sum of a chemical over every cell, in double.
double planeSum(const State& s, int chemical);

// A folder under the system's temporary folder for one test file's files (one per process),
// created if missing.
std::filesystem::path scratchDir(const std::string& name);

// scratchDir(name) / sub, emptied (removed and created again).
std::filesystem::path freshScratchDir(const std::string& name, const std::string& sub);

// A whole file as text ("" when it cannot be read).
std::string readTextFile(const std::filesystem::path& path);

// Runs a session on the CPU backend from its initial condition.
State runCpu(const Session& session);

} // namespace morphogen::test
