#include "core/models/turing_mcgraw.hpp"

#include "core/models/react_row.hpp"

namespace morphogen {

TuringMcGrawModel::TuringMcGrawModel() {
    constexpr float inf = std::numeric_limits<float>::infinity();
    m_name = "turing_mcgraw";
    m_description = "Turing activator-substrate as McGraw writes it (alpha, beta)";
    m_chemicals = {{"u", "du", 0.0f, inf, -1.0f, 1e3f}, {"v", "dv", 0.0f, inf, -1.0f, 1e3f}};
    m_params = {{"alpha", 12.0f, 0.0f, 100.0f, "decay offset of the activator u"},
                {"beta", 15.0f, 0.0f, 100.0f, "supply of the substrate v"},
                {"du", 2.0f, 0.0f, 100.0f, "diffusion rate of u (the activator)"},
                {"dv", 8.0f, 0.0f, 100.0f, "diffusion rate of v (the substrate)"}};
    m_displayChemical = 0;
    // Texture-set height levels: u spans 0..~8 (set (c) ~10) in the presets.
    m_chemicals[0].displayRange = {0.0f, 12.0f};
    m_chemicals[1].displayRange = {0.0f, 12.0f};
    m_defaultDt = 0.02f;
    m_defaultInit.base = {{"u", 4.0f}, {"v", 4.0f}};
    m_defaultInit.noise = {{"u", 2.0f}, {"v", 2.0f}};
}

void TuringMcGrawModel::react(const RowView& row, const float* p) const {
    reactRow<Cell>(row, p);
}

} // namespace morphogen
