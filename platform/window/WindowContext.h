// A window with an OpenGL 4.5 core context, through GLFW: the viewer's counterpart of
// HeadlessContext. Kept out of ml_platform (its own library, ml_window) so that nothing but
// the viewer links GLFW.
#pragma once

#include <string>

struct GLFWwindow;

namespace manylights {

struct WindowOptions {
    int width = 1280;
    int height = 720;
    std::string title = "manylights";
    bool debug = false;  // debug context + the synchronous error callback (as ContextOptions)
};

class WindowContext {
public:
    // Throws manylights::Error with one line (GLFW's reason) when no window can be made.
    explicit WindowContext(const WindowOptions& options);
    ~WindowContext();
    WindowContext(const WindowContext&) = delete;
    WindowContext& operator=(const WindowContext&) = delete;

    GLFWwindow* window() const { return window_; }
    // "GL_RENDERER (GL_VERSION) via GLFW".
    const std::string& description() const { return description_; }

private:
    GLFWwindow* window_ = nullptr;
    std::string description_;
};

}  // namespace manylights
