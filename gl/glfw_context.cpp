// GLFW window context: the designer's. The only file of gl/ that includes GLFW.

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <stdexcept>
#include <string>

#include "gl/context.hpp"
#include "gl/gl_loader.hpp"

namespace morphogen::gl {

namespace {

std::string lastGlfwError() {
    const char* description = nullptr;
    glfwGetError(&description);
    return description ? description : "unknown GLFW error";
}

class GlfwContext final : public Context {
public:
    explicit GlfwContext(GLFWwindow* window) : m_window(window) {}
    ~GlfwContext() override {
        glfwDestroyWindow(m_window);
        glfwTerminate();
    }
    GlfwContext(const GlfwContext&) = delete;
    GlfwContext& operator=(const GlfwContext&) = delete;

    ContextKind kind() const override { return ContextKind::Glfw; }
    void makeCurrent() override { glfwMakeContextCurrent(m_window); }

private:
    GLFWwindow* m_window;
};

} // namespace

std::unique_ptr<Context> createGlfwContext(int width, int height, const std::string& title,
                                           bool visible) {
    if (!glfwInit())
        throw std::runtime_error("GLFW: glfwInit failed: " + lastGlfwError() +
                                 " (is a display available?)");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
    GLFWwindow* window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window) {
        const std::string why = lastGlfwError();
        glfwTerminate();
        throw std::runtime_error("GLFW: cannot create a 3.3 core window: " + why);
    }
    auto context = std::make_unique<GlfwContext>(window);
    context->makeCurrent();
    loadGlFunctions(reinterpret_cast<ProcAddressFn>(&glfwGetProcAddress), "GLFW");
    return context;
}

} // namespace morphogen::gl
