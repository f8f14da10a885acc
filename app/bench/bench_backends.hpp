#pragma once

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/session/session.hpp"
#include "core/sim/simulator.hpp"

namespace morphogen::bench {

using Make = std::function<std::unique_ptr<Simulator>(const Session&)>;

// The simulators the domain and surface rows time, by backend name ("gpu",
// "cpu"), those asked for in that order.
std::vector<std::pair<std::string, Make>> simulatorBackends(bool gpu, bool cpu);

// Engine steps per second of `make`'s simulator of `s` from its initial
// state, batches of 20 for `seconds` after a warm-up batch (glFinish after
// each on the GPU).
double sessionStepsPerSecond(const Session& s, const Make& make, bool gpu, double seconds);

} // namespace morphogen::bench
