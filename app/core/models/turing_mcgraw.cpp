#include "core/models/turing_mcgraw.hpp"

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
    m_defaultDt = 0.02f;
    m_defaultInit.base = {{"u", 4.0f}, {"v", 4.0f}};
    m_defaultInit.noise = {{"u", 2.0f}, {"v", 2.0f}};
}

void TuringMcGrawModel::react(const RowView& row, const float* p) const {
    const float alpha = p[0], beta = p[1];
    const float* u = row.c[0];
    const float* v = row.c[1];
    float* du = row.dcdt[0];
    float* dv = row.dcdt[1];
#pragma omp simd
    for (int i = 0; i < row.n; ++i) {
        const float uv = u[i] * v[i];
        du[i] = uv - u[i] - alpha;
        dv[i] = beta - uv;
    }
}

} // namespace morphogen
