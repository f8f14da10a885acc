#include "core/models/meinhardt_stripes.hpp"

#include "core/models/react_row.hpp"

namespace morphogen {

MeinhardtStripesModel::MeinhardtStripesModel() {
    constexpr float inf = std::numeric_limits<float>::infinity();
    m_name = "meinhardt_stripes";
    m_description = "Meinhardt's five-chemical stripe system as Turk 1991 uses it (random stripes "
                    "from substrate noise, regular stripes from initiator cells)";
    m_chemicals = {{"g1", "Dg", 0.0f, inf, -1.0f, 1e3f}, {"g2", "Dg", 0.0f, inf, -1.0f, 1e3f},
                   {"r", "", kMinR, inf, -1.0f, 1e3f},   {"s1", "Ds", 0.0f, inf, -1.0f, 1e3f},
                   {"s2", "Ds", 0.0f, inf, -1.0f, 1e3f}, {"substrate", "", -inf, inf, -1e3f, 1e3f}};
    m_params = {
        {"c", 0.01f, 0.0f, 10.0f, "production rate of g1 and g2"},
        {"alpha", 0.04f, 0.0f, 10.0f, "decay rate of g1 and g2"},
        {"beta", 0.06f, 0.0f, 10.0f, "decay rate of r (the mutual exclusion)"},
        {"gamma", 0.04f, 0.0f, 10.0f, "rate at which s1, s2 follow g1, g2"},
        {"Dg", 0.009f, 0.0f, 10.0f, "diffusion rate of g1, g2 (Turk's Dx): larger, wider stripes"},
        {"Ds", 0.2f, 0.0f, 10.0f, "diffusion rate of s1, s2 (Turk's Dy)"},
        {"rho0", 0.0f, 0.0f, 10.0f, "basic production of g1, g2"},
        {"rho1", 0.0f, 0.0f, 10.0f, "basic production of s1, s2"}};
    m_displayChemical = 0;
    // Texture-set height levels: g1, g2 span 0..~1.5 in the stripe presets.
    m_chemicals[0].displayRange = {0.0f, 1.5f};
    m_chemicals[1].displayRange = {0.0f, 1.5f};
    m_defaultDt = 1.0f;
    // The homogeneous steady state for the default rates, g = beta / (2 alpha)
    // and r = 2 c g^3 / beta; the substrate's noise breaks its symmetry.
    const float g = 0.06f / (2.0f * 0.04f);
    m_defaultInit.base = {{"g1", g}, {"g2", g}, {"r", 2.0f * 0.01f * g * g * g / 0.06f},
                          {"s1", g}, {"s2", g}, {"substrate", 1.0f}};
    m_defaultInit.noise = {{"substrate", 0.005f}};
}

void MeinhardtStripesModel::react(const RowView& row, const float* p) const {
    reactRow<Cell>(row, p);
}

} // namespace morphogen
