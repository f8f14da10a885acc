#include "core/models/witkin_kass_multi.hpp"

#include <string>

#include "core/models/react_row.hpp"

namespace morphogen {

DiffusionSpec witkinKassMultiDiffusion(int pairs, float theta0, float e, float d, float s) {
    DiffusionSpec spec;
    spec.type = DiffusionType::Anisotropic;
    for (int i = 0; i < pairs; ++i) {
        const float theta = theta0 + 180.0f * float(i) / float(pairs);
        const std::string n = std::to_string(i + 1);
        spec.anisotropic["p" + n] = {theta, e * s, s};
        spec.anisotropic["m" + n] = {theta, e * s, d * s};
    }
    return spec;
}

template <int N, WkMultiReaction Kind> WitkinKassMultiModel<N, Kind>::WitkinKassMultiModel() {
    constexpr float inf = std::numeric_limits<float>::infinity();
    const std::string kind = kMaxOfDifferences ? "md" : "da";
    m_name = "witkin_kass_" + kind + std::to_string(N);
    m_glslFile = "witkin_kass_multi";
    m_glslDefines = {"WK_PAIRS " + std::to_string(N),
                     std::string("WK_REACTION ") + (kMaxOfDifferences ? "0" : "1")};
    m_description = "Witkin-Kass " + std::to_string(N) + "-direction " +
                    (kMaxOfDifferences ? "M-D (max of differences, eq. 14): weaves, lattices"
                                       : "D-A (difference of abs's, eq. 15): mazes");
    for (int i = 1; i <= N; ++i) {
        const std::string n = std::to_string(i);
        m_chemicals.push_back({"p" + n, "D", -inf, inf, -1e3f, 1e3f});
        m_chemicals.push_back({"m" + n, "D", -inf, inf, -1e3f, 1e3f});
    }
    m_params = {
        {"k", 1.0f, -100.0f, 100.0f, "reaction constant added to every chemical where R fires"},
        {"b", 1.0f, 0.0f, 100.0f, "dissipation rate"}};
    if (kMaxOfDifferences)
        m_params.push_back({"threshold", 0.0f, -100.0f, 100.0f,
                            "R fires where the largest difference C+_i - C-_i exceeds it"});
    m_params.push_back(
        {"D", 1.0f, 0.0f, 100.0f, "diffusion rate of every chemical (times its tensor)"});
    m_displayChemical = 0;
    // Texture-set height levels: p1 spans ~0.1..3.7 in the maze and coral presets.
    for (ChemicalSpec& c : m_chemicals)
        c.displayRange = {0.0f, 4.0f};
    // Section 6.2's scales: h = 1, dt = 0.02, uniform random start in [-1, 1].
    m_defaultDt = 0.02f;
    for (const ChemicalSpec& c : m_chemicals) {
        m_defaultInit.base[c.name] = 0.0f;
        m_defaultInit.noise[c.name] = 1.0f;
    }
    // Isotropic diffusion gives every pair the same rates: no pattern. Pair i
    // diffuses along theta_i unless a session says otherwise.
    m_defaultDiffusion = witkinKassMultiDiffusion(N);
}

template <int N, WkMultiReaction Kind>
void WitkinKassMultiModel<N, Kind>::react(const RowView& row, const float* p) const {
    reactRow<Cell>(row, p);
}

template class WitkinKassMultiModel<2, WkMultiReaction::MaxOfDifferences>;
template class WitkinKassMultiModel<3, WkMultiReaction::MaxOfDifferences>;
template class WitkinKassMultiModel<5, WkMultiReaction::MaxOfDifferences>;
template class WitkinKassMultiModel<2, WkMultiReaction::DifferenceOfAbs>;
template class WitkinKassMultiModel<3, WkMultiReaction::DifferenceOfAbs>;
template class WitkinKassMultiModel<5, WkMultiReaction::DifferenceOfAbs>;

} // namespace morphogen
