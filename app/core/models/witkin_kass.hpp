#pragma once

#include "core/models/reaction_model.hpp"

namespace morphogen {

// Witkin & Kass's threshold system (eq. 1 and 13) for two morphogens C+ (p)
// and C- (m):
//   dC/dt = A : H(C) - b C + R,   R = k where C+ - C- > threshold, else 0 (for both)
// The paper's eq. 13 is threshold 0 (the default). Then on and off are
// symmetric (the kernel G+ - G- integrates to zero), so patterns settle near
// half on; a negative threshold favours "on" (large patches, a thin off
// network), a positive one "off" (isolated spots).
// Patterns come from the two diffusing differently: give them different
// anisotropic tensors (section 6.2's zebra: P+ = [theta, e s, s],
// P- = [theta, e s, d s]) or different isotropic rates Dp, Dm.
class WitkinKassModel : public ReactionModel {
public:
    struct Cell {
        static constexpr int kChemicals = 2;
        static constexpr bool diffuses(int) { return true; }
        explicit Cell(const float* p) : k(p[0]), b(p[1]), threshold(p[4]) {}
        MORPHOGEN_CELL_REACT void react(const float* c, float* dcdt) const {
            // A select, not a branch: it vectorises.
            const float r = c[0] - c[1] > threshold ? k : 0.0f;
            dcdt[0] = r - b * c[0];
            dcdt[1] = r - b * c[1];
        }
        float k, b, threshold;
    };

    WitkinKassModel();
    void react(const RowView& row, const float* params) const override;
};

} // namespace morphogen
