#include "core/models/watercolour.hpp"

#include <algorithm>
#include <cstring>

#include "core/base/noise_field.hpp"
#include "core/models/paper_texture.hpp"
#include "core/models/react_row.hpp"

namespace morphogen {

WatercolourModel::WatercolourModel() {
    constexpr float inf = std::numeric_limits<float>::infinity();
    m_name = "watercolour";
    m_description = "Watercolour on paper (Lo et al. 5.6): water and two pigments bleed, "
                    "settle on a generated paper where the water thins";
    // Water and suspended pigment are clamped at 0 (the defaults never go
    // below it, see the header); stickiness stays in 0..1.
    m_chemicals = {{"w", "Dw", 0.0f, inf, -1.0f, 1e3f},  {"p1", "Dp", 0.0f, inf, -1.0f, 1e3f},
                   {"p2", "Dp", 0.0f, inf, -1.0f, 1e3f}, {"s", "", 0.0f, 1.0f, -1.0f, 2.0f},
                   {"d1", "", -inf, inf, -1.0f, 1e3f},   {"d2", "", -inf, inf, -1.0f, 1e3f},
                   {"g", "", -inf, inf, -1e6f, 1e6f}};
    m_params = {
        {"Dw", 0.2f, 0.0f, 0.25f, "diffusion rate of water (fast: the wash spreads)"},
        {"Dp", 0.18f, 0.0f, 0.25f, "diffusion rate of suspended pigment (slower than water)"},
        {"evaporation", 0.002f, 0.0f, 0.1f, "water lost to the air per unit time and area"},
        {"absorption", 0.004f, 0.0f, 0.1f,
         "water soaked into the paper per unit time and area, times stickiness"},
        {"film", 0.05f, 0.001f, 1.0f, "water depth below which the film breaks up and dries fast"},
        {"dry", 0.2f, 0.001f, 1.0f,
         "water depth below which suspended pigment is caught (the drying front)"},
        {"settle", 0.0002f, 0.0f, 0.5f, "rate pigment settles in deep water, times stickiness"},
        {"trap", 0.2f, 0.0f, 0.5f,
         "rate pigment settles where the water is thin (below `dry`), times stickiness"},
        {"paper_mean", 0.6f, 0.02f, 1.0f, "stickiness of the generated paper"},
        {"paper_grain", 0.3f, 0.0f, 2.0f, "relative strength of the paper's tooth"},
        {"paper_fibres", 0.15f, 0.0f, 2.0f, "relative strength of the paper's fibres"},
        {"paper_scale", 3.0f, 0.5f, 64.0f, "cells per grain of the paper"}};
    m_displayChemical = D1;
    m_chemicals[W].displayRange = {0.0f, 2.0f};
    m_chemicals[D1].displayRange = {0.0f, 1.0f};
    m_chemicals[D2].displayRange = {0.0f, 1.0f};
    m_defaultDt = 1.0f;
    // Without strokes: a few wet dabs of pigment 1, so the model alone shows a wash.
    m_defaultInit.type = InitialCondition::Type::SeedSpots;
    m_defaultInit.base = {{"w", 0.0f},  {"p1", 0.0f}, {"p2", 0.0f}, {"s", 0.6f},
                          {"d1", 0.0f}, {"d2", 0.0f}, {"g", 0.0f}};
    m_defaultInit.inside = {{"w", 1.0f}, {"p1", 0.5f}};
    m_defaultInit.spotCount = 6;
    m_defaultInit.spotRadius = 8.0f;
}

void WatercolourModel::react(const RowView& row, const float* p) const {
    reactRow<Cell>(row, p);
}

void WatercolourModel::prepareState(State& state, const ParamValues& values,
                                    const NoiseField& noise) const {
    PaperSpec spec;
    spec.seed = noise.seed();
    spec.mean = values.at("paper_mean");
    spec.grain = values.at("paper_grain");
    spec.fibres = values.at("paper_fibres");
    spec.scale = values.at("paper_scale");
    const std::vector<float> paper = makePaper(spec, state.width(), state.height());
    std::memcpy(state.plane(S), paper.data(), paper.size() * sizeof(float));
}

} // namespace morphogen
