#include "core/output/watercolour_paint.hpp"

#include <algorithm>
#include <cmath>

#include "core/models/reaction_model.hpp"
#include "core/models/watercolour.hpp"

namespace morphogen {

void paintWatercolourRow(const State& state, int y, const WatercolourLook& look, float* rgb) {
    using M = WatercolourModel;
    const std::size_t w = std::size_t(state.width());
    const std::size_t row = std::size_t(y) * w;
    const float* water = state.plane(M::W) + row;
    const float* stick = state.plane(M::S) + row;
    const float* wet[2] = {state.plane(M::P1) + row, state.plane(M::P2) + row};
    const float* dry[2] = {state.plane(M::D1) + row, state.plane(M::D2) + row};
    for (std::size_t x = 0; x < w; ++x) {
        const float tint =
            1.0f - look.grain * (stick[x] - 0.5f) - look.sheen * std::clamp(water[x], 0.0f, 1.0f);
        for (int c = 0; c < 3; ++c) {
            float optical = 0.0f;
            for (int k = 0; k < 2; ++k)
                optical +=
                    look.absorbance[k][c] * std::max(0.0f, dry[k][x] + look.wetShare * wet[k][x]);
            const float v = look.paper[c] * tint * std::exp(-optical);
            rgb[x * 3 + c] = std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f;
        }
    }
}

bool paintsAsWatercolour(const ReactionModel& model) {
    using M = WatercolourModel;
    return model.chemicals().size() == std::size_t(M::Cell::kChemicals) &&
           model.chemicalIndex("w") == M::W && model.chemicalIndex("s") == M::S &&
           model.chemicalIndex("p1") == M::P1 && model.chemicalIndex("p2") == M::P2 &&
           model.chemicalIndex("d1") == M::D1 && model.chemicalIndex("d2") == M::D2;
}

} // namespace morphogen
