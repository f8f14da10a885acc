#pragma once

#include <string>

#include <nlohmann/json_fwd.hpp>

namespace morphogen::bench {

// The resolution rows of `morphogen bench` (issue: the same look at any
// size): each preset rendered as `render --preset P --size N` renders it
// (until settled, the automatic plan, the backend `auto` picks) at every
// size, with its wall time, dominant wavelength and feature count in model
// units, and its correlation with the smallest size's result after
// area-averaging down to that size; then one preset at `compareSize`, refined
// (coarse-to-fine) against every step run at that size.
struct ResolutionBenchFlags {
    std::string sizes = "256,512,1024,2048";
    // Spots, stripes, a cascade.
    std::string presets = "turk_large_spots,wk_zebra,turk_leopard";
    int compareSize = 512; // 0: no refined-versus-direct row
};

// Refuses bad flags (InputError) before any row of the bench runs.
void checkResolutionFlags(const ResolutionBenchFlags& flags);

// Runs the rows, prints their table on stdout and returns them as JSON;
// `context` and `gpuDevice` are the bench's --context and --gpu-device.
nlohmann::json benchResolution(const ResolutionBenchFlags& flags, const std::string& context,
                               const std::string& gpuDevice);

} // namespace morphogen::bench
