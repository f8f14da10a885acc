#pragma once
// JSON and text files the user gives (sessions, presets, palettes), read
// within the limits of core/base/limits.hpp: every problem is an InputError of
// one line naming the file, never a library exception or a crash.

#include <cstddef>
#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

namespace morphogen {

// The deepest nesting of arrays and objects in `text`, counting brackets
// outside strings; stops counting once it passes `stopAbove` (the result is
// then stopAbove + 1). `offset` is set to where that depth was first reached.
int jsonNestingDepth(std::string_view text, int stopAbove, std::size_t* offset = nullptr);

// Parses `text` from `source` (a file name or "preset X"): text over
// kMaxJsonBytes or nested deeper than kMaxJsonDepth is refused before it is
// parsed; syntax errors and numbers out of a double's range are refused with
// the parser's position.
nlohmann::json parseJsonText(std::string_view text, const std::string& source);

// The contents of a file the user named: a missing or unreadable file, a
// folder, or a file over kMaxJsonBytes is refused. `what` names the kind of
// file in messages ("session file", "palette file").
std::string readInputFile(const std::string& path, const std::string& what);

// `text` as one line of at most `maxLength` characters: line breaks and other
// control characters become spaces (runs of them one), the ends are trimmed,
// and a longer text ends in "...". For messages that quote a library.
std::string oneLine(std::string_view text, std::size_t maxLength = 400);

} // namespace morphogen
