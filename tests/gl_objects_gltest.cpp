// The GL layer: contexts, RAII objects, shader errors.

#include <cstdlib>

#include <gtest/gtest.h>

#include "core/base/errors.hpp"
#include "gl/gl_checks.hpp"
#include "gl/objects.hpp"
#include "gl_test_support.hpp"

using namespace morphogen;

TEST(GlContext, IsTheKindCtestAskedFor) {
    gl::Context& context = test::glContext();
    const char* env = std::getenv(gl::kContextEnvVar);
    if (env && *env)
        EXPECT_EQ(gl::toString(context.kind()), env);
    EXPECT_FALSE(context.renderer().empty());
    EXPECT_NO_THROW(gl::verifyFloatRenderTargets());
}

TEST(GlContext, EglNamesTheDisplayItChose) {
    gl::Context& context = test::glContext();
    if (context.kind() != gl::ContextKind::Egl)
        GTEST_SKIP() << "an EGL test; this run's context is " << context.description();
    EXPECT_EQ(context.description().rfind("egl ", 0), 0u) << context.description();
    EXPECT_EQ(context.isSoftwareRenderer(), gl::isSoftwareRendererName(context.renderer()));
}

TEST(GlContext, AnotherEglDisplayLeavesTheFirstContextWorking) {
    if (test::glContext().kind() != gl::ContextKind::Egl)
        GTEST_SKIP() << "an EGL test";
    // Every other display candidate in turn: choosing it must not terminate
    // the display the first context lives on.
    auto first = gl::createHeadlessContext(gl::ContextKind::Egl);
    int others = 0;
    for (int index = 0; index < 8; ++index) {
        std::unique_ptr<gl::Context> other;
        try {
            other = gl::createHeadlessContext(gl::ContextKind::Egl, index);
        } catch (const InputError& e) {
            const std::string message = e.what();
            if (message.find("out of range") != std::string::npos)
                break;
            continue; // a candidate that fails here
        }
        others += other->description() != first->description();
        other.reset();
        first->makeCurrent();
        EXPECT_NO_THROW(gl::verifyFloatRenderTargets()) << "after " << index;
    }
    std::fprintf(stderr, "[gl] %d other EGL displays tried beside %s\n", others,
                 first->description().c_str());
    test::glContext();
}

TEST(GlContext, UnknownKindInTheEnvironmentIsNamed) {
    EXPECT_FALSE(gl::parseContextKind("vulkan"));
    EXPECT_EQ(gl::parseContextKind("osmesa"), gl::ContextKind::OsMesa);
}

TEST(GlObjects, MoveLeavesTheSourceEmpty) {
    test::glContext();
    gl::Texture2D a(8, 8, GL_RGBA32F);
    const GLuint id = a.id();
    ASSERT_NE(id, 0u);
    gl::Texture2D b(std::move(a));
    EXPECT_EQ(a.id(), 0u);
    EXPECT_EQ(b.id(), id);
    gl::Texture2D c;
    c = std::move(b);
    EXPECT_EQ(b.id(), 0u);
    EXPECT_EQ(c.id(), id);
    EXPECT_TRUE(glIsTexture(id));
    c = gl::Texture2D();
    EXPECT_FALSE(glIsTexture(id)); // the move-assignment released the old name
}

TEST(GlObjects, TextureRoundTripsFloatsExactly) {
    test::glContext();
    gl::Texture2D t(3, 2, GL_RGBA32F);
    std::vector<float> data(3 * 2 * 4);
    for (std::size_t i = 0; i < data.size(); ++i)
        data[i] = float(i) * 0.3183099f - 2.0f;
    t.uploadRgba(data);
    EXPECT_EQ(t.downloadRgba(), data);
}

TEST(GlObjects, OversizedTextureIsAnInputError) {
    test::glContext();
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    try {
        gl::Texture2D t(maxSize + 1, 4, GL_RGBA32F);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("largest texture"), std::string::npos);
    }
}

TEST(GlObjects, ShaderErrorsNameTheFileAndCarryTheLog) {
    test::glContext();
    const gl::ShaderPiece broken{"glsl/broken_on_purpose.frag",
                                 "out vec4 o;\nvoid main() { o = vec4(undefinedThing); }\n"};
    try {
        gl::Program p({gl::embeddedShader("glsl/fullscreen.vert")}, {broken}, {});
        FAIL();
    } catch (const std::runtime_error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("glsl/broken_on_purpose.frag"), std::string::npos) << message;
        EXPECT_NE(message.find("undefinedThing"), std::string::npos) << message;
        EXPECT_NE(message.find("source 1 = glsl/broken_on_purpose.frag"), std::string::npos);
    }
    EXPECT_THROW(gl::embeddedShader("glsl/missing.frag"), std::runtime_error);
}
