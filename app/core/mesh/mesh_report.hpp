#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "core/mesh/mesh_check.hpp"
#include "core/mesh/mesh_io.hpp"

namespace morphogen {

// The report `morphogen mesh-info` prints: the file, welding, size, each
// component's genus and boundary loops, and the problems found (with the
// verdict of requireManifold). Lines end in '\n'.
std::string meshReportText(const LoadedMesh& loaded, const MeshReport& report);

// The same as JSON ("usable" is report.usableForTiles()).
nlohmann::json meshReportJson(const LoadedMesh& loaded, const MeshReport& report);

} // namespace morphogen
