#pragma once

#include <string>
#include <vector>

#include "core/numerics/kernel.hpp"

namespace morphogen {

// Which monomials x^i y^j the local polynomial may use.
//
// TotalDegree (the default): i + j <= degree, fitted by least squares. On the
// 5x5 window with degree 4 this is 15 unknowns for 25 samples, so the kernels
// smooth across neighbouring rows/columns as Savitzky-Golay intends; it is the
// well-posed neighbour of McGraw's "degree 5" fit (total degree 5 is
// rank-deficient on 5 points per axis: x^5 and 5x^3 - 4x agree on -2..2) and
// the basis DESIGN.md's stability figures refer to.
//
// TensorProduct: i <= degree and j <= degree (eq. 32). With degree 2r on a
// (2r+1)^2 window the system is square and the fit interpolates, so each
// kernel is the outer product of two 1-D (2r+1)-point finite differences: no
// smoothing, and the 4th-derivative kernels touch only the centre row/column.
enum class SgBasis { TotalDegree, TensorProduct };

struct SgOptions {
    int radius = 2; // window side 2 * radius + 1; 1 or 2 (a Kernel5 holds at most 5x5)
    int degree = 4;
    SgBasis basis = SgBasis::TotalDegree;
};

// "total degree 4 on 5x5", for messages and reports.
std::string describe(const SgOptions& options);

// The fitted polynomial's derivatives at the window centre as convolution
// kernels. Construction does the one least-squares solve; kernels are then
// rows of the pseudoinverse scaled by p! q!.
class SavitzkyGolay {
public:
    // Throws InputError when the window or degree is out of range, or when the
    // basis is rank-deficient on the window (its kernels would not be exact).
    explicit SavitzkyGolay(const SgOptions& options = {});

    const SgOptions& options() const { return m_options; }

    // True when x^p y^q is in the basis, i.e. derivative(p, q) is defined.
    bool hasDerivative(int p, int q) const;

    // The kernel K with sum K.at(dx, dy) * c(x + dx, y + dy) = d^(p+q) c / dx^p dy^q
    // at (x, y), exact for every polynomial in the basis. +x to the right,
    // +y to increasing row index. Throws InputError when x^p y^q is not in the
    // basis (e.g. d^4/dx^2dy^2 needs degree >= 4 in the total-degree basis).
    Kernel5 derivative(int p, int q) const;

private:
    int columnOf(int p, int q) const; // -1 when not in the basis

    SgOptions m_options;
    int m_columns = 0;
    // Pseudoinverse rows, m_pinv[column * samples + sample], samples in row-major
    // window order (dy outer, dx inner).
    std::vector<double> m_pinv;
    std::vector<int> m_powersX, m_powersY;
};

} // namespace morphogen
