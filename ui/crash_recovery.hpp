#pragma once
// The designer's unsaved work after a crash. Each designer autosaves to a
// file of its own (autosave-PID.json in the state folder), so two designers
// never write one file, and a new designer never writes over what a crashed
// one left: at start, the autosaves of designers that no longer run are
// renamed to recovered-*.json, which nothing writes to, and stay there until
// the user restores or discards them.

#include <string>
#include <vector>

namespace morphogen::ui {

// The autosave of the designer process `pid`.
std::string autosavePathFor(const std::string& stateDir, long pid);

// Renames every autosave whose designer no longer runs (autosave-PID.json,
// and autosave.json as older versions named it) to
// recovered-YYYYMMDD-HHMMSS-N.json (the autosave's time; never over another
// file). Returns every recovered-*.json in `stateDir`, newest first. Never
// throws: a file it cannot rename is reported on stderr and left.
std::vector<std::string> keepCrashedAutosaves(const std::string& stateDir);

// Takes a recovered file out of the offer once the user restored it: renamed
// to restored-*.json beside it (never over another file). Returns the new
// path; throws std::filesystem::filesystem_error when it cannot rename.
std::string markRestored(const std::string& recovered);

} // namespace morphogen::ui
