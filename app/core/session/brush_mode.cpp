#include "core/session/brush_mode.hpp"

#include "core/base/enum_names.hpp"

namespace morphogen {

namespace {

constexpr EnumName<BrushMode> kBrushModeNames[] = {
    {BrushMode::Add, "add"},         {BrushMode::Remove, "remove"},
    {BrushMode::Set, "set"},         {BrushMode::Hold, "hold"},
    {BrushMode::Release, "release"}, {BrushMode::Randomise, "randomise"},
    {BrushMode::Paint, "paint"},
};
constexpr EnumAlias<BrushMode> kBrushModeAliases[] = {{"randomize", BrushMode::Randomise},
                                                      {"distort", BrushMode::Randomise}};

} // namespace

std::string toString(BrushMode mode) {
    return nameOf(kBrushModeNames, mode);
}

std::optional<BrushMode> parseBrushMode(std::string_view name) {
    return valueNamed(kBrushModeNames, kBrushModeAliases, name);
}

std::string brushModeNames() {
    return nameList(kBrushModeNames);
}

} // namespace morphogen
