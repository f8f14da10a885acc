#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace morphogen {

class ReactionModel;

enum class Stencil {
    FivePoint, // lap = l + r + u + d - 4c
    NinePoint, // lap = (4 (l + r + u + d) + corners - 20c) / 6: more isotropic
};
std::string toString(Stencil stencil);
// toString's spellings; std::nullopt for others. stencilNames() lists them.
std::optional<Stencil> parseStencil(std::string_view name);
std::string stencilNames();

enum class DiffusionType {
    Isotropic,   // D lap(c), 5- or 9-point
    Anisotropic, // Witkin-Kass: A : H(c), A from (theta, a1, a2), 3x3 mask (eq. 6-7)
    Generalized, // McGraw: rank 2-4 tensor sequence as one 5x5 Savitzky-Golay kernel
};
std::string toString(DiffusionType type);

// Witkin-Kass's triple: a1 is the rate along the principal direction at angle
// theta (degrees, counter-clockwise on the displayed image, 0 = +x), a2 across
// it; the tensor is A = a1^2 v v^T + a2^2 w w^T (eq. 6), times the model's
// diffusion rate for the chemical.
struct AnisotropicTensor {
    float theta = 0.0f;
    float a1 = 1.0f;
    float a2 = 1.0f;
};

// Where a diffusion map's principal direction comes from, per texel.
struct OrientationField {
    enum class Type { Constant, Radial, Concentric, Spiral, Vortex, Blend, ImageGradient };
    Type type = Type::Constant;
    float angle = 0.0f;                   // Constant: the angle; Spiral/Vortex: the twist (degrees)
    float centreX = 0.5f, centreY = 0.5f; // Radial..Vortex: centre as a fraction of the grid
    std::vector<OrientationField> parts;  // Blend: fields merged by inverse-distance weights
    std::string image;                    // ImageGradient: the image file
};
std::string toString(OrientationField::Type type);

// A diffusion map: the tensor varies per texel. Each chemical's tensor is
// rotated by the field's angle and scaled by s(x) in [scaleMin, scaleMax]
// (from an image's luminance when scaleImage is set, else scaleMax).
struct DiffusionMapSpec {
    OrientationField orientation;
    std::string scaleImage;
    float scaleMin = 1.0f;
    float scaleMax = 1.0f;
};

struct SavitzkyGolaySpec {
    int window = 5;
    int degree = 4;
    bool centralSecondOrder = true; // McGraw's stability remedy
};

struct DiffusionSpec {
    DiffusionType type = DiffusionType::Isotropic;
    Stencil stencil = Stencil::FivePoint;                 // Isotropic
    std::map<std::string, AnisotropicTensor> anisotropic; // Anisotropic, by chemical
    std::map<std::string, std::string> generalized;       // Generalized: "a".."f" or "xx=1,..."
    SavitzkyGolaySpec savitzkyGolay;                      // Generalized
    bool stabilize =
        true; // Generalized: damp modes whose symbol has Re > 0 (see kernel_symbol.hpp)
    std::optional<DiffusionMapSpec> map; // Anisotropic only
};

// Reads "diffusion" of a session; errors name `source` and the field.
DiffusionSpec diffusionFromJson(const nlohmann::json& json, const std::string& source,
                                const ReactionModel& model);
nlohmann::json diffusionToJson(const DiffusionSpec& spec);

} // namespace morphogen
