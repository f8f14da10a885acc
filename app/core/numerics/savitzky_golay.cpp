#include "core/numerics/savitzky_golay.hpp"

#include <cmath>
#include <sstream>

#include <Eigen/Dense>

#include "core/base/errors.hpp"

namespace morphogen {

namespace {

double factorial(int n) {
    double f = 1;
    for (int i = 2; i <= n; ++i)
        f *= i;
    return f;
}

bool inBasis(const SgOptions& o, int i, int j) {
    if (i < 0 || j < 0)
        return false;
    return o.basis == SgBasis::TotalDegree ? i + j <= o.degree : i <= o.degree && j <= o.degree;
}

} // namespace

std::string describe(const SgOptions& o) {
    std::ostringstream os;
    const int side = 2 * o.radius + 1;
    os << (o.basis == SgBasis::TotalDegree ? "total degree " : "tensor-product degree ") << o.degree
       << " on " << side << "x" << side;
    return os.str();
}

SavitzkyGolay::SavitzkyGolay(const SgOptions& options) : m_options(options) {
    const SgOptions& o = m_options;
    if (o.radius < 1 || o.radius > 2)
        throw InputError("Savitzky-Golay window radius " + std::to_string(o.radius) +
                         ": accepted are 1 (3x3) and 2 (5x5)");
    if (o.degree < 1)
        throw InputError("Savitzky-Golay degree " + std::to_string(o.degree) +
                         ": must be at least 1");
    for (int i = 0; i <= 2 * o.degree; ++i)
        for (int j = 0; j <= 2 * o.degree; ++j)
            if (inBasis(o, i, j)) {
                m_powersX.push_back(i);
                m_powersY.push_back(j);
            }
    m_columns = int(m_powersX.size());
    const int side = 2 * o.radius + 1;
    const int samples = side * side;

    Eigen::MatrixXd x(samples, m_columns);
    for (int dy = -o.radius; dy <= o.radius; ++dy)
        for (int dx = -o.radius; dx <= o.radius; ++dx) {
            const int row = (dy + o.radius) * side + (dx + o.radius);
            for (int c = 0; c < m_columns; ++c)
                x(row, c) = std::pow(double(dx), m_powersX[std::size_t(c)]) *
                            std::pow(double(dy), m_powersY[std::size_t(c)]);
        }

    // A basis with more than 2r + 1 powers along an axis has a monomial that
    // agrees with a lower-degree one on every sample (x^5 vs 5x^3 - 4x on
    // -2..2): the fit cannot tell them apart, so no kernel would be exact.
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(x, Eigen::ComputeThinU | Eigen::ComputeThinV);
    const Eigen::VectorXd& s = svd.singularValues();
    if (m_columns > samples || s(s.size() - 1) < 1e-10 * s(0)) {
        std::ostringstream os;
        os << "Savitzky-Golay basis " << describe(o) << " is rank-deficient (" << m_columns
           << " monomials, " << samples << " samples, rank " << svd.setThreshold(1e-10).rank()
           << "); use at most degree " << 2 * o.radius << " per axis, e.g. total degree "
           << 2 * o.radius << " (least squares) or tensor-product degree " << 2 * o.radius
           << " (interpolating)";
        throw InputError(os.str());
    }
    const Eigen::MatrixXd pinv =
        svd.matrixV() * s.cwiseInverse().asDiagonal() * svd.matrixU().transpose();
    m_pinv.resize(std::size_t(m_columns * samples));
    for (int c = 0; c < m_columns; ++c)
        for (int k = 0; k < samples; ++k)
            m_pinv[std::size_t(c * samples + k)] = pinv(c, k);
}

int SavitzkyGolay::columnOf(int p, int q) const {
    for (int c = 0; c < m_columns; ++c)
        if (m_powersX[std::size_t(c)] == p && m_powersY[std::size_t(c)] == q)
            return c;
    return -1;
}

bool SavitzkyGolay::hasDerivative(int p, int q) const {
    return columnOf(p, q) >= 0;
}

Kernel5 SavitzkyGolay::derivative(int p, int q) const {
    const int c = columnOf(p, q);
    if (c < 0)
        throw InputError("Savitzky-Golay basis " + describe(m_options) + " has no x^" +
                         std::to_string(p) + " y^" + std::to_string(q) +
                         " term, so it cannot give that derivative; raise the degree");
    const int r = m_options.radius;
    const int side = 2 * r + 1;
    const double scale = factorial(p) * factorial(q);
    Kernel5 k;
    for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
            const int sample = (dy + r) * side + (dx + r);
            double v = scale * m_pinv[std::size_t(c * side * side + sample)];
            // Exact zeros keep Kernel5::radius() meaningful and the symmetry
            // tests exact; entries below this are pure rounding.
            if (std::abs(v) < 1e-13)
                v = 0.0;
            k.at(dx, dy) = v;
        }
    return k;
}

} // namespace morphogen
