// The designer's context: a visible GLFW window (ctest runs this under
// xvfb-run), buffer swaps, and a backend made on the window's context
// without owning it.

#include <gtest/gtest.h>

#include <glad/gl.h>

#include "core/models/initial_condition.hpp"
#include "gl/backend.hpp"
#include "gl/glfw_context.hpp"
#include "test_support.hpp"

using namespace morphogen;

namespace {

// The default framebuffer's pixel at (1, 1) after clearing it to `rgba`.
std::array<unsigned char, 4> clearAndRead(const std::array<float, 4>& rgba) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glClearColor(rgba[0], rgba[1], rgba[2], rgba[3]);
    glClear(GL_COLOR_BUFFER_BIT);
    std::array<unsigned char, 4> pixel{};
    glReadBuffer(GL_BACK);
    glReadPixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel.data());
    return pixel;
}

gl::GlfwContext& window() {
    static std::unique_ptr<gl::GlfwContext> context =
        gl::createGlfwContext(64, 48, "morphogen glfw test", true);
    context->makeCurrent();
    return *context;
}

} // namespace

TEST(GlfwContext, IsAVisibleWindowThatClearsAndSwaps) {
    gl::GlfwContext& context = window();
    EXPECT_EQ(context.kind(), gl::ContextKind::Glfw);
    EXPECT_EQ(context.description(), "glfw");
    ASSERT_NE(context.window(), nullptr);
    EXPECT_FALSE(context.shouldClose());
    const auto [width, height] = context.framebufferSize();
    EXPECT_EQ(width, 64);
    EXPECT_EQ(height, 48);
    std::fprintf(stderr, "[gl] glfw window: %s, %s\n", context.renderer().c_str(),
                 context.version().c_str());

    EXPECT_EQ(clearAndRead({1, 0, 0, 1}), (std::array<unsigned char, 4>{255, 0, 0, 255}));
    context.swapBuffers();
    EXPECT_EQ(clearAndRead({0, 1, 0, 1}), (std::array<unsigned char, 4>{0, 255, 0, 255}));
    context.swapBuffers();
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));

    context.setShouldClose(true);
    EXPECT_TRUE(context.shouldClose());
    context.setShouldClose(false);
}

TEST(GlfwContext, GpuBackendRunsOnTheWindowWithoutOwningIt) {
    gl::GlfwContext& context = window();
    const Session session = test::smallSession("gs_coral", 16, 20);
    {
        gl::Backend backend = gl::makeBackend(gl::BackendChoice::Gpu, context);
        EXPECT_TRUE(backend.usesGpu);
        EXPECT_EQ(backend.context, nullptr);
        EXPECT_NE(backend.reason.find("gpu backend (requested: glfw, "), std::string::npos)
            << backend.reason;
        auto simulator = backend.makeSimulator(session);
        EXPECT_EQ(simulator->backendName(), "gpu");
        simulator->setState(makeInitialState(session.init, session.reactionModel(), session.params,
                                             session.width, session.height, session.seed));
        simulator->run(session.steps);
        const State gpu = simulator->state();
        const State cpu = test::runCpu(session);
        EXPECT_LE(test::maxAbsDifference(gpu, cpu), 1e-4f * test::maxAbsValue(cpu));
    }
    // The backend is gone; the window's context still draws.
    EXPECT_EQ(clearAndRead({0, 0, 1, 1}), (std::array<unsigned char, 4>{0, 0, 255, 255}));
    context.swapBuffers();
}

TEST(GlfwContext, AutoBackendFollowsTheWindowsRenderer) {
    gl::GlfwContext& context = window();
    gl::Backend backend = gl::makeBackend(gl::BackendChoice::Auto, context);
    EXPECT_EQ(backend.usesGpu, !context.isSoftwareRenderer()) << backend.reason;
    EXPECT_EQ(backend.context, nullptr);
    const auto simulator = backend.makeSimulator(test::smallSession("gs_coral", 8, 1));
    EXPECT_EQ(simulator->backendName(), backend.usesGpu ? "gpu" : "cpu");

    const gl::Backend cpu = gl::makeBackend(gl::BackendChoice::Cpu, context);
    EXPECT_FALSE(cpu.usesGpu);
    EXPECT_EQ(cpu.reason, "cpu backend (requested)");
}
