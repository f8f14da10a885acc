#pragma once

#include <string>
#include <vector>

#include "core/numerics/tensor_sequence.hpp"

namespace morphogen {

// McGraw's Gram-Charlier diffusion propagator (eq. 23-24): the probability
// density of a displacement r after time tau,
//     p(r) = N(r; 0, 2 tau D2) (1 - tau D3 : H3(r) + tau D4 : H4(r)),
// with Q^(n) / n! = (-1)^n tau D^(n) and ':' the full contraction. Its peaks
// on |r| = const are the pattern's preferred directions.
//
// Angles are measured from +x towards +y of the tensor's coordinates, which
// Morphogen takes as the display's (y up, so counter-clockwise on screen):
// compileDiffusion mirrors the grid kernels to match, so a peak at 30 degrees
// is a direction the texture shows at 30 degrees counter-clockwise from +x.
//
// H4 uses the standard Hermite tensor x_i x_j x_k x_l - 6 sym(delta_ij x_k x_l)
// + 3 sym(delta_ij delta_kl), whose 1-D form is He4 = x^4 - 6 x^2 + 3. The
// paper's appendix writes the last term as -3 delta_ijkl (1-D: x^4 - 6x^2 - 3);
// that only adds a tensor-dependent constant on |r| = 1, so the curve's shape
// and its peaks are the same either way.
class Propagator {
public:
    // Throws InputError when D^(2) is not positive definite (no Gaussian) or
    // tau <= 0.
    Propagator(const TensorSequence& sequence, double tau = 0.1);

    double operator()(double x, double y) const;
    // On the circle |r| = radius at angle `degrees`.
    double atAngle(double degrees, double radius = 1.0) const;
    // The Gaussian's standard deviation along its widest axis, sqrt of the
    // largest eigenvalue of 2 tau D2: radii of about 1 to 3 of it show the
    // propagator's shape.
    double width() const { return m_width; }

private:
    TensorSequence m_d;
    double m_tau;
    double m_inv[3]; // (2 tau D2)^-1 as xx, xy, yy
    double m_norm;   // 1 / (2 pi sqrt(det(2 tau D2)))
    double m_width;
};

// n samples of the propagator on |r| = radius, at angles 360 i / n degrees.
std::vector<double> sampleAngular(const Propagator& p, double radius, int n = 3600);

// What angular samples of a propagator can show. Empty: no sample is a
// positive finite number (the density underflowed to 0 at that radius, or
// only the Gram-Charlier series' negative tails are left, or it overflowed):
// the plot has nothing in it and there is no direction to read. Isotropic:
// constant up to rounding. Directional: the rest, with findAngularPeaks'
// peaks.
enum class AngularShape { Empty, Isotropic, Directional };
AngularShape angularShape(const std::vector<double>& samples);

// Directions (degrees in [0, 360), ascending) of the local maxima of a
// periodic angular function sampled at 360 i / n degrees, refined by a
// parabola through each peak and its neighbours. A function that is constant
// up to rounding (isotropic) has none.
std::vector<double> findAngularPeaks(const std::vector<double>& samples);

// A polar plot of the samples as an interleaved RGB float image (size x size,
// white background): grey axes and reference circles, the curve filled in a
// light tint and outlined thickly in a strong colour, radius proportional to
// the value and the maximum filling ~90% of the half-width. Drawn with +y
// up, like the rendered texture, so the lobes point the way the texture runs.
// Negative values (Gram-Charlier tails) are drawn at radius 0.
std::vector<float> renderPolarPlot(const std::vector<double>& samples, int size = 512);

} // namespace morphogen
