#pragma once

#include <nlohmann/json_fwd.hpp>

namespace morphogen::cli {

// The domain rows of `morphogen bench`, printed and returned as JSON:
// throughput per texel of the cube and rotated-tile atlases as a fraction of
// the grid of the same texture size on each backend, and a batched sweep
// (one tiled-grid simulation) against its tiles run one by one. The GPU rows
// run when `gpu` is true (a context is current); `seconds` per measurement.
nlohmann::json benchDomains(bool gpu, bool cpu, double seconds);

} // namespace morphogen::cli
