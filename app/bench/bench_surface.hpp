#pragma once

#include <nlohmann/json_fwd.hpp>

namespace morphogen::bench {

// The surface rows of `morphogen bench` (issue 11), printed and returned as
// JSON: the seconds from a mesh file to a running atlas for a model of about
// 100k triangles (the blob sample at level 6, written to a temporary OBJ and
// read back), phase by phase; and the global throughput per texel on a real
// mesh atlas (the holes sample at the automatic tile budget, with its metric
// weights) as a fraction of a flat grid of the same texel count, on each
// backend (the GPU when `gpu`: a context is current); and the seconds of a
// session step on three models (the blob, the scan-like sample, the blob at
// level 6) explicit and semi-implicit, against a flat grid of as many cells
// of a texel's size. `seconds` per measurement.
nlohmann::json benchSurface(bool gpu, bool cpu, double seconds);

} // namespace morphogen::bench
