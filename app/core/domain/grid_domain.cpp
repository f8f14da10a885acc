#include "core/domain/grid_domain.hpp"

#include "core/base/enum_names.hpp"

namespace morphogen {

namespace {

const EnumName<EdgeMode> kEdgeModes[] = {{EdgeMode::Periodic, "periodic"},
                                         {EdgeMode::Clamped, "clamped"}};

const EnumAlias<EdgeMode> kEdgeModeAliases[] = {
    {"wrap", EdgeMode::Periodic}, {"clamp", EdgeMode::Clamped}, {"zero-flux", EdgeMode::Clamped}};

} // namespace

std::string toString(EdgeMode mode) {
    return nameOf(kEdgeModes, mode);
}

std::optional<EdgeMode> parseEdgeMode(std::string_view name) {
    return valueNamed(kEdgeModes, kEdgeModeAliases, name);
}

std::string edgeModeNames() {
    return nameList(kEdgeModes);
}

} // namespace morphogen
