// GLFW window context: the designer's. The only file of gl/ that includes GLFW.

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <stdexcept>
#include <string>

#include "gl/gl_loader.hpp"
#include "gl/glfw_context.hpp"

namespace morphogen::gl {

namespace {

std::string lastGlfwError() {
    const char* description = nullptr;
    glfwGetError(&description);
    return description ? description : "unknown GLFW error";
}

// Windows alive: glfwTerminate would destroy every one of them, so it waits
// for the last.
int g_liveWindows = 0;

} // namespace

GlfwContext::GlfwContext(GLFWwindow* window) : m_window(window) {
    ++g_liveWindows;
}

GlfwContext::~GlfwContext() {
    glfwDestroyWindow(m_window);
    if (--g_liveWindows == 0)
        glfwTerminate();
}

void GlfwContext::makeCurrent() {
    glfwMakeContextCurrent(m_window);
}

void GlfwContext::swapBuffers() {
    glfwSwapBuffers(m_window);
}

void GlfwContext::setSwapInterval(int interval) {
    makeCurrent();
    glfwSwapInterval(interval);
}

bool GlfwContext::shouldClose() const {
    return glfwWindowShouldClose(m_window) != 0;
}

void GlfwContext::setShouldClose(bool close) {
    glfwSetWindowShouldClose(m_window, close ? GLFW_TRUE : GLFW_FALSE);
}

std::pair<int, int> GlfwContext::framebufferSize() const {
    int width = 0, height = 0;
    glfwGetFramebufferSize(m_window, &width, &height);
    return {width, height};
}

std::unique_ptr<GlfwContext> createGlfwContext(int width, int height, const std::string& title,
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
        if (g_liveWindows == 0)
            glfwTerminate();
        throw std::runtime_error("GLFW: cannot create a 3.3 core window: " + why);
    }
    auto context = std::make_unique<GlfwContext>(window);
    context->makeCurrent();
    loadGlFunctions(reinterpret_cast<ProcAddressFn>(&glfwGetProcAddress), "GLFW");
    return context;
}

} // namespace morphogen::gl
