#include "core/models/witkin_kass.hpp"

#include "core/models/react_row.hpp"

namespace morphogen {

WitkinKassModel::WitkinKassModel() {
    constexpr float inf = std::numeric_limits<float>::infinity();
    m_name = "witkin_kass";
    m_description = "Witkin-Kass threshold reaction (zebra, sand ripples with anisotropy)";
    m_chemicals = {{"p", "Dp", -inf, inf, -1e3f, 1e3f}, {"m", "Dm", -inf, inf, -1e3f, 1e3f}};
    m_params = {{"k", 1.0f, -100.0f, 100.0f, "reaction constant added where C+ > C-"},
                {"b", 1.0f, 0.0f, 100.0f, "dissipation rate"},
                {"Dp", 1.0f, 0.0f, 100.0f, "diffusion rate of C+ (times its tensor)"},
                {"Dm", 1.0f, 0.0f, 100.0f, "diffusion rate of C- (times its tensor)"},
                {"threshold", 0.0f, -100.0f, 100.0f,
                 "the reaction fires where C+ - C- exceeds it (eq. 13: 0)"}};
    m_displayChemical = 0;
    // Texture-set height levels: p spans ~0.05..0.96 in the stripe presets.
    m_chemicals[0].displayRange = {0.0f, 1.0f};
    m_chemicals[1].displayRange = {0.0f, 1.0f};
    // Section 6.2: h = 1, dt = 0.02, both morphogens start as noise in [-1, 1].
    m_defaultDt = 0.02f;
    m_defaultInit.base = {{"p", 0.0f}, {"m", 0.0f}};
    m_defaultInit.noise = {{"p", 1.0f}, {"m", 1.0f}};
}

void WitkinKassModel::react(const RowView& row, const float* p) const {
    reactRow<Cell>(row, p);
}

} // namespace morphogen
