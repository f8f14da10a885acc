#pragma once

#include "gl/context.hpp"

namespace morphogen::test {

// The process-wide context for *_gltest, created on first use from
// $MORPHOGEN_CONTEXT (ctest runs each gltest under egl and under osmesa).
gl::Context& glContext();

} // namespace morphogen::test
