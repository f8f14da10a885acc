#pragma once

// Loads the GL 3.3 core entry points (glad2) through the current context's
// getProcAddress. Context backends call it right after making their context
// current; it throws std::runtime_error if the context is below 3.3 core.

namespace morphogen::gl {

using ProcAddressFn = void (*(*)(const char*))();
void loadGlFunctions(ProcAddressFn getProcAddress, const char* backendName);

} // namespace morphogen::gl
