#pragma once

#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace morphogen::bench {

// The model rows of `morphogen bench`, printed and returned as JSON: the
// watercolour model's explicit step against a Gray-Scott step of the same
// size in the same run, on each backend (the GPU rows when `gpu`: a context
// is current). The figure is the time ratio watercolour / Gray-Scott (issue
// 13 asks for at most 1.5), each model's best of three alternating rounds.
// `seconds` per measurement, split over the rounds.
nlohmann::json benchModels(const std::vector<int>& sizes, bool gpu, bool cpu, double seconds);

} // namespace morphogen::bench
