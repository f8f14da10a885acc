#pragma once

#include <array>
#include <string>

#include <CLI/CLI.hpp>

#include "core/session/session.hpp"

namespace morphogen::cli {

// `--colours LIST` and `--palette FILE`: a custom gradient, shared by `render` and `colour`.
struct GradientFlags {
    std::string colours; // "#1b1b1b,#d9a441,#f4e8c1"
    std::string palette; // a palette file (core/session/gradient.hpp)
};

// Registers --colours and --palette on `cmd`.
void addGradientFlags(CLI::App& cmd, GradientFlags& flags);

// Applies the flags to `spec` after --colormap (`colormapFlag`, empty when not
// given) has set its name: stops make the map "custom"; another map named by
// --colormap drops a session's stops. Then checks the map (name, stop count),
// so bad input is found before a run. Throws InputError.
void applyGradientFlags(const GradientFlags& flags, const std::string& colormapFlag,
                        ColorMapSpec& spec);

// "LOW:HIGH" with 0 <= LOW < HIGH <= 1 for `flag`; throws InputError.
std::array<float, 2> parseLevelsFlag(const std::string& flag, const std::string& text);

} // namespace morphogen::cli
