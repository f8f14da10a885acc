#include "gl_test_support.hpp"

#include <cstdio>
#include <memory>

namespace morphogen::test {

gl::Context& glContext() {
    static std::unique_ptr<gl::Context> context = [] {
        auto c = gl::createHeadlessContext();
        std::fprintf(stderr, "[gl] %s context: %s, %s\n", gl::toString(c->kind()).c_str(),
                     c->renderer().c_str(), c->version().c_str());
        return c;
    }();
    context->makeCurrent();
    return *context;
}

} // namespace morphogen::test
