#include "core/models/gray_scott.hpp"

#include "core/models/react_row.hpp"

namespace morphogen {

GrayScottModel::GrayScottModel() {
    m_name = "gray_scott";
    m_description = "Gray-Scott (Pearson's regimes): spots, mitosis, coral, worms, waves";
    m_chemicals = {{"u", "Du", -std::numeric_limits<float>::infinity(),
                    std::numeric_limits<float>::infinity(), -1.0f, 2.0f},
                   {"v", "Dv", -std::numeric_limits<float>::infinity(),
                    std::numeric_limits<float>::infinity(), -1.0f, 2.0f}};
    m_params = {{"F", 0.0367f, 0.0f, 0.2f, "feed rate"},
                {"k", 0.0649f, 0.0f, 0.2f, "kill rate"},
                {"Du", 0.2097f, 0.0f, 10.0f, "diffusion rate of u (cell^2 per unit time)"},
                {"Dv", 0.105f, 0.0f, 10.0f, "diffusion rate of v (cell^2 per unit time)"}};
    m_displayChemical = 1;
    // Texture-set height levels: u falls from 1 to ~0.2 in a pattern; v peaks
    // near 0.4 in Pearson's patterns (coral, mitosis, worms at 0.38..0.43).
    m_chemicals[0].displayRange = {0.0f, 1.0f};
    m_chemicals[1].displayRange = {0.0f, 0.5f};
    // Pearson's dt = 1 sits on the stability edge in high-v states
    // (8 Du + v^2 + F ~ 2.05 at F 0.06, k 0.03): it leaves a period-2
    // checkerboard there. 0.9 keeps every preset stable.
    m_defaultDt = 0.9f;
    m_defaultInit.type = InitialCondition::Type::SeedSpots;
    m_defaultInit.base = {{"u", 1.0f}, {"v", 0.0f}};
    m_defaultInit.inside = {{"u", 0.5f}, {"v", 0.25f}};
    m_defaultInit.noise = {{"u", 0.01f}, {"v", 0.01f}};
    m_defaultInit.spotCount = 20;
    m_defaultInit.spotRadius = 4.0f;
}

void GrayScottModel::react(const RowView& row, const float* p) const {
    reactRow<Cell>(row, p);
}

} // namespace morphogen
