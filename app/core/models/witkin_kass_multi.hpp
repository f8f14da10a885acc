#pragma once

#include <algorithm>
#include <cmath>

#include "core/models/reaction_model.hpp"

namespace morphogen {

// Witkin & Kass's competing orientations (section 6.3): N antagonistic pairs
// (C+_i, C-_i), chemicals p1, m1, p2, m2, ..., each pair biased towards its
// own direction theta_i = theta0 + 180 i / N by its anisotropic tensors
// (section 6.2: P+_i = [theta_i, e s, s], P-_i = [theta_i, e s, d s]).
// With D_i = C+_i - C-_i, every chemical gets the same reaction R and
// dissipates at rate b:
//   dC/dt = A : H(C) - b C + R
//   M-D (eq. 14): R = k if max_j D_j > threshold, else 0 (woven threads)
//   D-A (eq. 15): R = k if |max_j D_j| > |min_j D_j|, else 0 (mazes)
// Scale: the pattern's width comes from the diffusion lengths sqrt(D a^2 / b)
// (a = a1, a2 of the tensors), about 1-1.5 cells with section 6.2's b = 1,
// D = 1. The presets use b = 0.25 (twice the lengths: patterns ~13 cells
// across), dt 0.05 (the 3x3 kernels' explicit limit is ~0.08 at D = 1) and
// 4000 steps (t = 200, 50 dissipation times). M-D's threshold sets how much
// of the plane fires: with k = 1, b = 0.25 the differences stay within a few
// tenths; 0 fires almost everywhere, ~0.1 gives lattices and threads, and
// above ~0.2 (2 pairs) the pattern dies out.
enum class WkMultiReaction {
    MaxOfDifferences, // M-D, eq. 14
    DifferenceOfAbs,  // D-A, eq. 15
};

template <int N, WkMultiReaction Kind> class WitkinKassMultiModel : public ReactionModel {
public:
    static constexpr int kPairs = N;
    static constexpr bool kMaxOfDifferences = Kind == WkMultiReaction::MaxOfDifferences;

    // Parameters in declaration order: k, b, then threshold (M-D only), then D.
    struct Cell {
        static constexpr int kChemicals = 2 * N;
        static constexpr bool diffuses(int) { return true; }
        explicit Cell(const float* p)
            : k(p[0]), b(p[1]), threshold(kMaxOfDifferences ? p[2] : 0.0f) {}
        MORPHOGEN_CELL_REACT void react(const float* c, float* dcdt) const {
            float hi = c[0] - c[1], lo = hi;
            for (int i = 1; i < N; ++i) {
                const float d = c[2 * i] - c[2 * i + 1];
                hi = std::max(hi, d);
                lo = std::min(lo, d);
            }
            // Selects, not branches: they vectorise.
            const bool fires = kMaxOfDifferences ? hi > threshold : std::fabs(hi) > std::fabs(lo);
            const float r = fires ? k : 0.0f;
            for (int j = 0; j < kChemicals; ++j)
                dcdt[j] = r - b * c[j];
        }
        float k, b, threshold;
    };

    WitkinKassMultiModel();
    void react(const RowView& row, const float* params) const override;
};

using WitkinKassMd2 = WitkinKassMultiModel<2, WkMultiReaction::MaxOfDifferences>;
using WitkinKassMd3 = WitkinKassMultiModel<3, WkMultiReaction::MaxOfDifferences>;
using WitkinKassMd5 = WitkinKassMultiModel<5, WkMultiReaction::MaxOfDifferences>;
using WitkinKassDa2 = WitkinKassMultiModel<2, WkMultiReaction::DifferenceOfAbs>;
using WitkinKassDa3 = WitkinKassMultiModel<3, WkMultiReaction::DifferenceOfAbs>;
using WitkinKassDa5 = WitkinKassMultiModel<5, WkMultiReaction::DifferenceOfAbs>;

extern template class WitkinKassMultiModel<2, WkMultiReaction::MaxOfDifferences>;
extern template class WitkinKassMultiModel<3, WkMultiReaction::MaxOfDifferences>;
extern template class WitkinKassMultiModel<5, WkMultiReaction::MaxOfDifferences>;
extern template class WitkinKassMultiModel<2, WkMultiReaction::DifferenceOfAbs>;
extern template class WitkinKassMultiModel<3, WkMultiReaction::DifferenceOfAbs>;
extern template class WitkinKassMultiModel<5, WkMultiReaction::DifferenceOfAbs>;

// The default tensors of an N-direction model (section 6.2's zebra ratios
// e = 2, d = 1.5, s = 1 for every pair, pair i at theta0 + 180 i / N with
// theta0 = 0): what a session without a "diffusion" block gets.
DiffusionSpec witkinKassMultiDiffusion(int pairs, float theta0 = 0.0f, float e = 2.0f,
                                       float d = 1.5f, float s = 1.0f);

} // namespace morphogen
