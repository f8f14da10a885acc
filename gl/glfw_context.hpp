#pragma once

// The designer's context: a GLFW window with a 3.3 core context. This header
// does not include GLFW (gl/ never does outside glfw_context.cpp); the window
// is handed out as GLFW's own opaque type for Dear ImGui's GLFW backend
// (ImGui_ImplGlfw_InitForOpenGL) and the designer's event loop.

#include <memory>
#include <string>
#include <utility>

#include "gl/context.hpp"

struct GLFWwindow;

namespace morphogen::gl {

class GlfwContext final : public Context {
public:
    // Takes ownership of `window`; GLFW stays initialised while any window lives.
    explicit GlfwContext(GLFWwindow* window);
    ~GlfwContext() override;
    GlfwContext(const GlfwContext&) = delete;
    GlfwContext& operator=(const GlfwContext&) = delete;

    ContextKind kind() const override { return ContextKind::Glfw; }
    void makeCurrent() override;

    GLFWwindow* window() const { return m_window; }
    // Presents the back buffer (the default framebuffer, 0).
    void swapBuffers();
    // 1 waits for vertical sync, 0 does not; applies to this context when current.
    void setSwapInterval(int interval);
    // The user asked to close the window (its close button, or setShouldClose).
    bool shouldClose() const;
    void setShouldClose(bool close);
    // The default framebuffer's size in pixels (differs from the window's size
    // in screen units on high-DPI displays).
    std::pair<int, int> framebufferSize() const;

private:
    GLFWwindow* m_window;
};

// Opens a window (shown when `visible`) with a current 3.3 core context and GL
// loaded; throws std::runtime_error saying why not (no display, no 3.3 core).
std::unique_ptr<GlfwContext> createGlfwContext(int width, int height, const std::string& title,
                                               bool visible);

} // namespace morphogen::gl
