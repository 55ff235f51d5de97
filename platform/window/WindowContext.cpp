#include "platform/window/WindowContext.h"

#include <epoxy/gl.h>
#include <GLFW/glfw3.h>

#include "core/Error.h"
#include "gl/Debug.h"

namespace manylights {

namespace {

// GLFW reports errors through a callback; the last one explains a failed call.
std::string& lastGlfwError()
{
    static std::string message;
    return message;
}

void recordGlfwError(int /*code*/, const char* description) { lastGlfwError() = description ? description : ""; }

}  // namespace

WindowContext::WindowContext(const WindowOptions& options)
{
    glfwSetErrorCallback(recordGlfwError);
    if (!glfwInit())
        throw Error("cannot open a window: " + lastGlfwError() + " (is DISPLAY set? under ssh or CI use xvfb-run)");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, options.debug ? GLFW_TRUE : GLFW_FALSE);
    // No multisampling: the window shows the renderer's image as it is.
    glfwWindowHint(GLFW_SAMPLES, 0);
    window_ = glfwCreateWindow(options.width, options.height, options.title.c_str(), nullptr, nullptr);
    if (!window_) {
        const std::string reason = lastGlfwError();
        glfwTerminate();
        throw Error("cannot open an OpenGL 4.5 core window: " + reason);
    }
    glfwMakeContextCurrent(window_);
    // Frame times are what the viewer shows: no waiting for the display's refresh.
    glfwSwapInterval(0);
    if (options.debug)
        gl::installErrorCallback();
    description_ = std::string(reinterpret_cast<const char*>(glGetString(GL_RENDERER))) + " (" +
                   reinterpret_cast<const char*>(glGetString(GL_VERSION)) + ") via GLFW";
}

WindowContext::~WindowContext()
{
    glfwDestroyWindow(window_);
    glfwTerminate();
}

}  // namespace manylights
