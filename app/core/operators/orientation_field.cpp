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
    std::vector<float> angles(jxx.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            double a = 0, b = 0, c = 0;
            for (int v = -r; v <= r; ++v)
                for (int u = -r; u <= r; ++u) {
                    const std::size_t i = std::size_t(std::clamp(y + v, 0, h - 1)) * w +
                                          std::size_t(std::clamp(x + u, 0, w - 1));
                    a += jxx[i];
                    b += jxy[i];
                    c += jyy[i];
                }
            // The gradient's doubled angle; isolines run perpendicular to it.
            angles[std::size_t(y) * w + x] = float(0.5 * std::atan2(2 * b, a - c) + kPi / 2);
        }
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
    // part's centre: a smooth merger of several fields.
    std::vector<std::vector<float>> parts;
    for (const OrientationField& p : field.parts)
        parts.push_back(orientationAngles(p, width, height, baseDir));
    const double soften = 0.01 * double(width) * width;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            double cx = 0, cy = 0;
            for (std::size_t k = 0; k < parts.size(); ++k) {
                const double dx = x + 0.5 - field.parts[k].centreX * width;
                const double dy = y + 0.5 - field.parts[k].centreY * height;
                const double weight = 1.0 / (dx * dx + dy * dy + soften);
                const double a = 2.0 * parts[k][std::size_t(y) * width + x];
                cx += weight * std::cos(a);
                cy += weight * std::sin(a);
            }
            angles[std::size_t(y) * width + x] = float(0.5 * std::atan2(cy, cx));
        }
    return angles;
}

} // namespace morphogen
