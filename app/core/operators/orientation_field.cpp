#include "core/operators/orientation_field.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/io/image_io.hpp"

namespace morphogen {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree = kPi / 180.0;

std::string resolve(const std::string& path, const std::string& baseDir) {
    const std::filesystem::path p(path);
    if (p.is_absolute() || baseDir.empty())
        return path;
    return (std::filesystem::path(baseDir) / p).string();
}

// Angle of the field at a point in display coordinates (y up), relative to the centre.
double analyticAngle(const OrientationField& f, double x, double y, int width, int height) {
    const double dx = x - f.centreX * width;
    const double dy = -(y - f.centreY * height); // rows grow downward; display y grows upward
    const double radial = std::atan2(dy, dx);
    switch (f.type) {
    case OrientationField::Type::Constant:
        return f.angle * kDegree;
    case OrientationField::Type::Radial:
        return radial;
    case OrientationField::Type::Concentric:
        return radial + kPi / 2;
    case OrientationField::Type::Spiral:
        return radial + f.angle * kDegree;
    case OrientationField::Type::Vortex: {
        // Concentric near the centre, twisting by `angle` at the grid's half-width.
        const double r = std::sqrt(dx * dx + dy * dy) / (0.5 * std::min(width, height));
        return radial + kPi / 2 + f.angle * kDegree * r;
    }
    default:
        return 0.0;
    }
}

// Sums of `values` (w x h) over the (2r + 1)^2 box around each cell, edges
// clamped: one running sum along the rows, then one down the columns, so the
// cost does not grow with r (r is a 32nd of the grid). A window of zeros sums
// to exactly 0, as a direct sum would (a flat region's angle depends on it),
// not to the running sum's rounding residue.
void boxSum(std::vector<double>& values, int w, int h, int r) {
    std::vector<double> line;
    auto slide = [&](int n, auto&& at) {
        line.assign(std::size_t(n), 0.0);
        double sum = 0;
        int nonzero = 0;
        for (int u = -r; u <= r; ++u) {
            const double v = at(std::clamp(u, 0, n - 1));
            sum += v;
            nonzero += v != 0.0;
        }
        for (int x = 0; x < n; ++x) {
            line[std::size_t(x)] = nonzero > 0 ? sum : 0.0;
            const double in = at(std::min(x + r + 1, n - 1)), out = at(std::max(x - r, 0));
            sum += in - out;
            nonzero += int(in != 0.0) - int(out != 0.0);
        }
    };
    for (int y = 0; y < h; ++y) {
        double* row = &values[std::size_t(y) * w];
        slide(w, [&](int x) { return row[x]; });
        std::copy(line.begin(), line.end(), row);
    }
    for (int x = 0; x < w; ++x) {
        slide(h, [&](int y) { return values[std::size_t(y) * w + x]; });
        for (int y = 0; y < h; ++y)
            values[std::size_t(y) * w + x] = line[std::size_t(y)];
    }
}

std::vector<float> imageGradientAngles(const std::string& path, int w, int h) {
    const std::vector<float> lum = loadLuminance(path, w, h);
    auto at = [&](int x, int y) {
        x = std::clamp(x, 0, w - 1);
        y = std::clamp(y, 0, h - 1);
        return lum[std::size_t(y) * w + x];
    };
    // Structure tensor of the gradient (display coordinates), box-smoothed so
    // that flat regions inherit the orientation of nearby edges.
    std::vector<double> jxx(std::size_t(w) * h), jxy(jxx.size()), jyy(jxx.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double gx = 0.5 * (at(x + 1, y) - at(x - 1, y));
            const double gy = -0.5 * (at(x, y + 1) - at(x, y - 1));
            const std::size_t i = std::size_t(y) * w + x;
            jxx[i] = gx * gx;
            jxy[i] = gx * gy;
            jyy[i] = gy * gy;
        }
    const int r = std::max(1, std::min(w, h) / 32);
    boxSum(jxx, w, h, r);
    boxSum(jxy, w, h, r);
    boxSum(jyy, w, h, r);
    std::vector<float> angles(jxx.size());
    for (std::size_t i = 0; i < angles.size(); ++i)
        // The gradient's doubled angle; isolines run perpendicular to it.
        angles[i] = float(0.5 * std::atan2(2 * jxy[i], jxx[i] - jyy[i]) + kPi / 2);
    return angles;
}

} // namespace

std::vector<float> orientationAngles(const OrientationField& field, int width, int height,
                                     const std::string& baseDir) {
    if (field.type == OrientationField::Type::ImageGradient)
        return imageGradientAngles(resolve(field.image, baseDir), width, height);

    std::vector<float> angles(std::size_t(width) * height);
    if (field.type != OrientationField::Type::Blend) {
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x)
                angles[std::size_t(y) * width + x] =
                    float(analyticAngle(field, x + 0.5, y + 0.5, width, height));
        return angles;
    }

    // Blend: orientations are axial (theta ~ theta + pi), so average the
    // doubled-angle vectors, weighted by inverse squared distance to each
    // part's centre: a smooth merger of several fields. Parts are added one
    // at a time (in order, so the sums are the same), holding one part's
    // angles at a time rather than all of them.
    std::vector<double> cx(angles.size(), 0.0), cy(angles.size(), 0.0);
    const double soften = 0.01 * double(width) * width;
    for (const OrientationField& part : field.parts) {
        const std::vector<float> partAngles = orientationAngles(part, width, height, baseDir);
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const std::size_t i = std::size_t(y) * width + x;
                const double dx = x + 0.5 - part.centreX * width;
                const double dy = y + 0.5 - part.centreY * height;
                const double weight = 1.0 / (dx * dx + dy * dy + soften);
                const double a = 2.0 * partAngles[i];
                cx[i] += weight * std::cos(a);
                cy[i] += weight * std::sin(a);
            }
    }
    for (std::size_t i = 0; i < angles.size(); ++i)
        angles[i] = float(0.5 * std::atan2(cy[i], cx[i]));
    return angles;
}

} // namespace morphogen
