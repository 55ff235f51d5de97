#include "platform/HeadlessContext.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "core/Error.h"
#include "gl/Debug.h"

namespace manylights {

namespace {

bool hasExtension(const char* extensions, const char* name)
{
    if (!extensions)
        return false;
    const std::size_t length = std::strlen(name);
    for (const char* p = std::strstr(extensions, name); p; p = std::strstr(p + 1, name))
        if ((p == extensions || p[-1] == ' ') && (p[length] == ' ' || p[length] == '\0'))
            return true;
    return false;
}

struct Candidate {
    EGLDisplay display;
    std::string platform;
};

std::vector<Candidate> candidateDisplays()
{
    std::vector<Candidate> candidates;
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (hasExtension(clientExtensions, "EGL_EXT_device_enumeration") &&
        hasExtension(clientExtensions, "EGL_EXT_platform_device")) {
        EGLint count = 0;
        eglQueryDevicesEXT(0, nullptr, &count);
        std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(std::max(count, 0)));
        if (count > 0 && eglQueryDevicesEXT(count, devices.data(), &count)) {
            // Hardware first: Mesa also lists its software rasteriser as a device.
            std::stable_partition(devices.begin(), devices.end(), [](EGLDeviceEXT device) {
                return !hasExtension(eglQueryDeviceStringEXT(device, EGL_EXTENSIONS), "EGL_MESA_device_software");
            });
            for (EGLDeviceEXT device : devices) {
                EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
                if (display != EGL_NO_DISPLAY)
                    candidates.push_back({display, "EGL device"});
            }
        }
    }
    if (hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (display != EGL_NO_DISPLAY)
            candidates.push_back({display, "EGL surfaceless"});
    }
    if (EGLDisplay display = eglGetDisplay(EGL_DEFAULT_DISPLAY); display != EGL_NO_DISPLAY)
        candidates.push_back({display, "EGL default display"});
    return candidates;
}

EGLContext createContext(EGLDisplay display, bool debug)
{
    if (!eglBindAPI(EGL_OPENGL_API))
        return EGL_NO_CONTEXT;
    const EGLint configAttributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configCount = 0;
    const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
    // Rendering goes to framebuffer objects only: no surface, so a config is a formality,
    // and with EGL_KHR_no_config_context not even that.
    if (!hasExtension(extensions, "EGL_KHR_no_config_context") &&
        (!eglChooseConfig(display, configAttributes, &config, 1, &configCount) || configCount == 0))
        return EGL_NO_CONTEXT;
    if (!hasExtension(extensions, "EGL_KHR_surfaceless_context"))
        return EGL_NO_CONTEXT;
    const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                        4,
                                        EGL_CONTEXT_MINOR_VERSION,
                                        5,
                                        EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                        EGL_CONTEXT_OPENGL_DEBUG,
                                        debug ? EGL_TRUE : EGL_FALSE,
                                        EGL_NONE};
    return eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttributes);
}

}  // namespace

bool defaultDebugContext()
{
#ifdef MANYLIGHTS_GL_DEBUG
    return true;
#else
    const char* flag = std::getenv("MANYLIGHTS_GL_DEBUG");
    return flag && std::strcmp(flag, "1") == 0;
#endif
}

HeadlessContext::HeadlessContext(const ContextOptions& options)
{
    std::string tried;
    for (const Candidate& candidate : candidateDisplays()) {
        EGLint major = 0;
        EGLint minor = 0;
        if (!eglInitialize(candidate.display, &major, &minor)) {
            tried += (tried.empty() ? "" : "; ") + candidate.platform + ": eglInitialize failed";
            continue;
        }
        EGLContext context = createContext(candidate.display, options.debug);
        if (context == EGL_NO_CONTEXT) {
            tried += (tried.empty() ? "" : "; ") + candidate.platform + ": no OpenGL 4.5 core context";
            eglTerminate(candidate.display);
            continue;
        }
        if (!eglMakeCurrent(candidate.display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
            tried += (tried.empty() ? "" : "; ") + candidate.platform + ": eglMakeCurrent failed";
            eglDestroyContext(candidate.display, context);
            eglTerminate(candidate.display);
            continue;
        }
        display_ = candidate.display;
        context_ = context;
        description_ = std::string(reinterpret_cast<const char*>(glGetString(GL_RENDERER))) + " (" +
                       reinterpret_cast<const char*>(glGetString(GL_VERSION)) + ") via " + candidate.platform;
        if (options.debug)
            gl::installErrorCallback();
        return;
    }
    throw Error("cannot create an OpenGL 4.5 core context (" + (tried.empty() ? std::string("no EGL display") : tried) +
                ")");
}

HeadlessContext::~HeadlessContext()
{
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    eglTerminate(display_);
}

}  // namespace manylights
