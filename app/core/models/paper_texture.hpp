#pragma once

#include <cstdint>
#include <vector>

namespace morphogen {

// Watercolour paper as a stickiness (absorption power) map, 0..1 per cell:
// a mean, a grain (isotropic value noise at `scale` cells: the paper's tooth)
// and fibres (thin ridges of value noise stretched 6:1 along three random
// directions, as pressed cellulose fibres lie in every direction).
struct PaperSpec {
    std::uint64_t seed = 1;
    float mean = 0.6f;    // the stickiness of smooth paper
    float grain = 0.3f;   // relative amplitude of the tooth
    float fibres = 0.15f; // relative amplitude of the fibres
    float scale = 3.0f;   // cells per grain; fibres are ~6x longer
};

// Row-major width x height values in [0.02, 1]: never 0, so every wet cell
// eventually settles its pigment. The same seed gives the same paper at a
// given size.
std::vector<float> makePaper(const PaperSpec& spec, int width, int height);

} // namespace morphogen
