#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "core/mesh/mesh_check.hpp"
#include "core/mesh/mesh_io.hpp"

namespace morphogen {

// The report `morphogen mesh-info` prints: the file, welding, size, each
// component's genus and boundary loops, what the repair changed, and the
// problems that remain (with the verdict of requireUsableForTiles). Lines end in '\n'.
std::string meshReportText(const LoadedMesh& loaded, const MeshReport& report);

// What repairMesh changed, one line without its end: "2 duplicate triangles
// removed, 1 vertex copied to cut sheets apart where they met" ("nothing").
std::string repairSummary(const RepairStats& repair);

// The same as JSON ("usable" is report.usableForTiles()).
nlohmann::json meshReportJson(const LoadedMesh& loaded, const MeshReport& report);

} // namespace morphogen
