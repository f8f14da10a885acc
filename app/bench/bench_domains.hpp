#pragma once

#include <nlohmann/json_fwd.hpp>

namespace morphogen::bench {

// The domain rows of `morphogen bench`, printed and returned as JSON:
// throughput per texel of the cube and rotated-tile atlases, plain and with
// per-texel weights, as a fraction of the grid of the same texture size on
// each backend; localized reaction-diffusion against global after a local
// perturbation on a 1024-tile atlas (time to re-equilibrium, Lo's Table 1
// phases); and a batched sweep (one tiled-grid simulation) against its tiles
// run one by one. The GPU rows
// run when `gpu` is true (a context is current); `seconds` per measurement.
nlohmann::json benchDomains(bool gpu, bool cpu, double seconds);

} // namespace morphogen::bench
