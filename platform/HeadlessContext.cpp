#include "platform/HeadlessContext.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "core/Error.h"
#include "gl/Debug.h"
#include "gl/Driver.h"

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

bool canEnumerateDevices()
{
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    return hasExtension(clientExtensions, "EGL_EXT_device_enumeration") &&
           hasExtension(clientExtensions, "EGL_EXT_platform_device");
}

// The EGL devices in the driver's order (the indices of --device), none where EGL cannot list
// them.
std::vector<EGLDeviceEXT> eglDevices()
{
    if (!canEnumerateDevices())
        return {};
    EGLint count = 0;
    if (!eglQueryDevicesEXT(0, nullptr, &count) || count <= 0)
        return {};
    std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
    if (!eglQueryDevicesEXT(count, devices.data(), &count))
        return {};
    devices.resize(static_cast<std::size_t>(std::max(count, 0)));
    return devices;
}

bool isSoftwareDevice(EGLDeviceEXT device)
{
    return hasExtension(eglQueryDeviceStringEXT(device, EGL_EXTENSIONS), "EGL_MESA_device_software");
}

std::optional<Candidate> deviceCandidate(EGLDeviceEXT device, int index)
{
    EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
    if (display == EGL_NO_DISPLAY)
        return std::nullopt;
    return Candidate{display, "EGL device " + std::to_string(index)};
}

// The displays to try in order: every device (hardware first: Mesa also lists its software
// rasteriser as a device), Mesa's surfaceless platform, the default display. With `device`,
// that device's display only.
std::vector<Candidate> candidateDisplays(std::optional<int> device)
{
    std::vector<Candidate> candidates;
    std::vector<EGLDeviceEXT> devices = eglDevices();
    if (device) {
        checkDeviceIndex(*device, devices.size());
        if (auto candidate = deviceCandidate(devices[static_cast<std::size_t>(*device)], *device))
            candidates.push_back(*candidate);
        return candidates;
    }
    std::vector<int> order(devices.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = static_cast<int>(i);
    std::stable_partition(order.begin(), order.end(),
                          [&](int i) { return !isSoftwareDevice(devices[static_cast<std::size_t>(i)]); });
    for (int i : order)
        if (auto candidate = deviceCandidate(devices[static_cast<std::size_t>(i)], i))
            candidates.push_back(*candidate);
    const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
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

// A context made current on `display`, or the reason none could be: eglInitialize, then a
// 4.5 core context, then eglMakeCurrent. The display is terminated again on failure.
struct CurrentContext {
    EGLContext context = EGL_NO_CONTEXT;
    std::string problem;
};
CurrentContext makeCurrentContext(EGLDisplay display, bool debug)
{
    EGLint major = 0;
    EGLint minor = 0;
    if (!eglInitialize(display, &major, &minor))
        return {EGL_NO_CONTEXT, "eglInitialize failed"};
    EGLContext context = createContext(display, debug);
    if (context == EGL_NO_CONTEXT) {
        eglTerminate(display);
        return {EGL_NO_CONTEXT, "no OpenGL 4.5 core context"};
    }
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        eglDestroyContext(display, context);
        eglTerminate(display);
        return {EGL_NO_CONTEXT, "eglMakeCurrent failed"};
    }
    return {context, ""};
}

std::string glString(GLenum name)
{
    const auto* text = reinterpret_cast<const char*>(glGetString(name));
    return text ? text : "";
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

void checkDeviceIndex(int index, std::size_t count)
{
    if (index < 0 || static_cast<std::size_t>(index) >= count)
        throw Error("--device " + std::to_string(index) + ": no such EGL device (there " +
                    (count == 1 ? std::string("is 1") : "are " + std::to_string(count)) +
                    "; manylights devices lists them)");
}

HeadlessContext::HeadlessContext(const ContextOptions& options)
{
    std::string tried;
    for (const Candidate& candidate : candidateDisplays(options.device)) {
        const CurrentContext made = makeCurrentContext(candidate.display, options.debug);
        if (made.context == EGL_NO_CONTEXT) {
            tried += (tried.empty() ? "" : "; ") + candidate.platform + ": " + made.problem;
            continue;
        }
        display_ = candidate.display;
        context_ = made.context;
        description_ = glString(GL_RENDERER) + " (" + glString(GL_VERSION) + ") via " + candidate.platform;
        if (options.debug)
            gl::installErrorCallback();
        return;
    }
    throw Error("cannot create an OpenGL 4.5 core context (" + (tried.empty() ? std::string("no EGL display") : tried) +
                ")");
}

std::vector<EglDeviceInfo> listDevices()
{
    std::vector<EglDeviceInfo> list;
    const std::vector<EGLDeviceEXT> devices = eglDevices();
    for (std::size_t i = 0; i < devices.size(); ++i) {
        EglDeviceInfo info;
        info.index = static_cast<int>(i);
        info.software = isSoftwareDevice(devices[i]);
        if (hasExtension(eglQueryDeviceStringEXT(devices[i], EGL_EXTENSIONS), "EGL_EXT_device_drm"))
            if (const char* file = eglQueryDeviceStringEXT(devices[i], EGL_DRM_DEVICE_FILE_EXT))
                info.drmFile = file;
        const std::optional<Candidate> candidate = deviceCandidate(devices[i], info.index);
        const CurrentContext made = candidate ? makeCurrentContext(candidate->display, false)
                                              : CurrentContext{EGL_NO_CONTEXT, "no EGL display"};
        if (made.context == EGL_NO_CONTEXT) {
            info.problem = made.problem;
        } else {
            info.vendor = glString(GL_VENDOR);
            info.renderer = glString(GL_RENDERER);
            info.software = info.software || gl::isSoftwareRendererName(info.renderer);
            eglMakeCurrent(candidate->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
            eglDestroyContext(candidate->display, made.context);
            eglTerminate(candidate->display);
        }
        list.push_back(std::move(info));
    }
    return list;
}

HeadlessContext::~HeadlessContext()
{
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display_, context_);
    eglTerminate(display_);
}

}  // namespace manylights
