#pragma once

#include <string>
#include <vector>

#include "core/models/diffusion_spec.hpp"

namespace morphogen {

// The principal direction of a diffusion map at every texel of a width x
// height grid, as an angle in radians, counter-clockwise on the displayed
// image (0 = +x). Analytic fields are evaluated at texel centres; an image
// field follows the image's isolines (the minor eigenvector of its smoothed
// structure tensor). Relative image paths resolve against baseDir.
std::vector<float> orientationAngles(const OrientationField& field, int width, int height,
                                     const std::string& baseDir);

} // namespace morphogen
