#pragma once

namespace morphogen::gl {

// Renders a known value into RGBA32F and RG32F targets and reads it back;
// throws std::runtime_error if float render targets do not work exactly.
// Called once per context at start-up.
void verifyFloatRenderTargets();

} // namespace morphogen::gl
