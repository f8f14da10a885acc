#include "core/models/turing_turk.hpp"

#include "core/base/noise_field.hpp"
#include "core/models/react_row.hpp"

namespace morphogen {

TuringTurkModel::TuringTurkModel() {
    constexpr float inf = std::numeric_limits<float>::infinity();
    m_name = "turing_turk";
    m_description = "Turing spots as Turk 1991 writes them (s sets the spot size)";
    m_chemicals = {{"a", "Da", -inf, inf, -1.0f, 1e3f},
                   {"b", "Db", 0.0f, inf, -1.0f, 1e3f},
                   {"beta", "", -inf, inf, -1e3f, 1e3f}};
    m_params = {{"s", 0.05f, 0.0f, 10.0f, "reaction rate: smaller s, larger spots"},
                {"Da", 1.0f, 0.0f, 10.0f, "diffusion rate of a (the inhibitor)"},
                {"Db", 0.25f, 0.0f, 10.0f, "diffusion rate of b"},
                {"beta_mean", 12.0f, 0.0f, 100.0f, "mean of the per-cell beta field"},
                {"beta_noise", 0.1f, 0.0f, 100.0f, "beta = beta_mean + U(-noise, noise)"}};
    m_displayChemical = 1;
    // Texture-set height levels: b spans 0..~7 in the spot presets (a, b start at 4).
    m_chemicals[0].displayRange = {0.0f, 8.0f};
    m_chemicals[1].displayRange = {0.0f, 8.0f};
    m_defaultDt = 0.18f;
    m_defaultInit.base = {{"a", 4.0f}, {"b", 4.0f}};
}

void TuringTurkModel::react(const RowView& row, const float* p) const {
    reactRow<Cell>(row, p);
}

void TuringTurkModel::prepareState(State& state, const ParamValues& values,
                                   const NoiseField& field) const {
    const float mean = values.at("beta_mean");
    const float noise = values.at("beta_noise");
    float* beta = state.plane(2);
    // Stream 1000 keeps beta's noise independent of the chemicals' noise streams.
    for (int y = 0; y < state.height(); ++y)
        for (int x = 0; x < state.width(); ++x)
            beta[std::size_t(y) * state.width() + x] = float(mean + noise * field.at(1000, x, y));
}

} // namespace morphogen
