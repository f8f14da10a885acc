#pragma once

namespace morphogen::cli {

// The variable `morphogen bench`'s memory rows set for the render they start:
// the file that render writes its peak resident memory to.
constexpr const char* kPeakMemoryEnv = "MORPHOGEN_PEAK_MEMORY_FILE";

// With $MORPHOGEN_PEAK_MEMORY_FILE set, writes this process's peak resident
// memory in kB (VmHWM of /proc/self/status, -1 without /proc) to that file
// when it exits. The render command calls it before it starts.
void writePeakMemoryAtExit();

} // namespace morphogen::cli
