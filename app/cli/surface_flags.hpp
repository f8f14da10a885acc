#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "core/session/session.hpp"

namespace morphogen::cli {

// --wrap's help, for render and mesh-info alike.
inline constexpr const char* kWrapHelp =
    "replace the mesh by its alpha wrap (a closed surface 0.17% of the diagonal outside it, "
    "gaps under 1% closed over): auto (default: when it is a soup of pieces, at least 32 of "
    "them mostly of 4 triangles or fewer), always, never";

// render's flags for growing a pattern on a mesh (the session's "surface"
// block, core/session/surface_spec.hpp). Numbers are text until applied, so a
// bad value is refused naming the flag.
struct SurfaceFlags {
    std::string mesh;
    std::string tileSize;
    std::string tiles;
    bool noMetricCorrection = false;
    bool noCrossTerm = false;
    bool noRepair = false;
    std::string mergeDistance;
    std::string wrap;
    std::string curvatureScale;
    std::string direction;
    std::string view;
    std::string resolution;
    std::string turntable;
};

void addSurfaceFlags(CLI::App& command, SurfaceFlags& flags);

// Whether any surface flag was given.
bool anySurfaceFlag(const SurfaceFlags& flags);

// Applies the flags to `session`: --mesh starts (or replaces) its surface;
// the other flags need a surface, from --mesh or the session. A mesh path
// from the command line is made absolute, so the written session finds it
// from any folder. Throws InputError naming the flag.
void applySurfaceFlags(const SurfaceFlags& flags, Session& session);

} // namespace morphogen::cli
