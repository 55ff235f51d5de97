#include "platform/HeadlessContext.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
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

// EGL_EXT_device_persistent_id, which libepoxy 1.5.10 (Debian 12) does not know: its entry
// point comes through eglGetProcAddress and its token from the Khronos registry (eglext.h).
constexpr EGLint kDeviceUuidExt = 0x335C;  // EGL_DEVICE_UUID_EXT
using QueryDeviceBinary = EGLBoolean (*)(EGLDeviceEXT device, EGLint name, EGLint maxSize, void* value, EGLint* size);

const char* clientExtensions() { return eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS); }

struct Candidate {
    EGLDisplay display;
    std::string platform;  // as HeadlessContext::description() names it
    std::string fallback;  // as the fallback note names it; "" for an EGL device
};

// The EGL devices in the driver's order (the indices of --device), none where EGL cannot list
// them.
std::vector<EGLDeviceEXT> eglDevices(const EglPlatformChoice& choice)
{
    if (!choice.canEnumerateDevices)
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

// The device's extensions, null where EGL cannot query devices.
const char* deviceExtensions(const EglPlatformChoice& choice, EGLDeviceEXT device)
{
    return choice.canQueryDevices ? eglQueryDeviceStringEXT(device, EGL_EXTENSIONS) : nullptr;
}

bool isSoftwareDevice(const EglPlatformChoice& choice, EGLDeviceEXT device)
{
    return hasExtensionToken(deviceExtensions(choice, device), "EGL_MESA_device_software");
}

std::optional<DeviceUuid> deviceUuid(const EglPlatformChoice& choice, EGLDeviceEXT device)
{
    if (!hasExtensionToken(deviceExtensions(choice, device), "EGL_EXT_device_persistent_id"))
        return std::nullopt;
    static const auto query = reinterpret_cast<QueryDeviceBinary>(eglGetProcAddress("eglQueryDeviceBinaryEXT"));
    DeviceUuid uuid{};
    EGLint size = 0;
    if (!query || !query(device, kDeviceUuidExt, static_cast<EGLint>(uuid.size()), uuid.data(), &size) ||
        size != static_cast<EGLint>(uuid.size()))
        return std::nullopt;
    return uuid;
}

std::optional<Candidate> deviceCandidate(EGLDeviceEXT device, std::size_t index)
{
    EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
    if (display == EGL_NO_DISPLAY)
        return std::nullopt;
    return Candidate{display, "EGL device " + std::to_string(index), ""};
}

// The displays to try in order: every device (hardware first: Mesa also lists its software
// rasteriser as a device), Mesa's surfaceless platform, the default display. With `device`,
// that device's display only.
std::vector<Candidate> candidateDisplays(const EglPlatformChoice& choice, const std::vector<EGLDeviceEXT>& devices,
                                         const std::optional<DeviceSelector>& device)
{
    std::vector<Candidate> candidates;
    if (device) {
        std::vector<std::optional<DeviceUuid>> uuids;
        for (EGLDeviceEXT each : devices)
            uuids.push_back(device->uuid ? deviceUuid(choice, each) : std::nullopt);
        const std::size_t index = selectDevice(*device, uuids, choice);
        if (auto candidate = deviceCandidate(devices[index], index))
            candidates.push_back(*candidate);
        return candidates;
    }
    std::vector<std::size_t> order(devices.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    std::stable_partition(order.begin(), order.end(),
                          [&](std::size_t i) { return !isSoftwareDevice(choice, devices[i]); });
    for (std::size_t i : order)
        if (auto candidate = deviceCandidate(devices[i], i))
            candidates.push_back(*candidate);
    if (choice.canUseSurfaceless) {
        EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (display != EGL_NO_DISPLAY)
            candidates.push_back({display, "EGL surfaceless", "Mesa's surfaceless platform"});
    }
    if (EGLDisplay display = eglGetDisplay(EGL_DEFAULT_DISPLAY); display != EGL_NO_DISPLAY)
        candidates.push_back({display, "EGL default display", "EGL's default display"});
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
    if (!hasExtensionToken(extensions, "EGL_KHR_no_config_context") &&
        (!eglChooseConfig(display, configAttributes, &config, 1, &configCount) || configCount == 0))
        return EGL_NO_CONTEXT;
    if (!hasExtensionToken(extensions, "EGL_KHR_surfaceless_context"))
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

EglPlatformChoice eglPlatformChoice() { return chooseEglPlatforms(clientExtensions()); }

std::size_t selectListedDevice(const DeviceSelector& selector, const std::vector<EglDeviceInfo>& devices)
{
    std::vector<std::optional<DeviceUuid>> uuids;
    for (const EglDeviceInfo& device : devices)
        uuids.push_back(device.uuid);
    return selectDevice(selector, uuids, eglPlatformChoice());
}

HeadlessContext::HeadlessContext(const ContextOptions& options)
{
    const EglPlatformChoice choice = eglPlatformChoice();
    const std::vector<EGLDeviceEXT> devices = eglDevices(choice);
    std::string tried;
    for (const Candidate& candidate : candidateDisplays(choice, devices, options.device)) {
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
        // Silent on the device platform, as every test on llvmpipe expects; the one exception
        // to the rule that the libraries print nothing (CODE_STYLE.md), because every command
        // that renders would otherwise have to repeat it.
        static std::atomic<bool> noted{false};
        if (!candidate.fallback.empty() && !noted.exchange(true))
            std::fprintf(
                stderr, "manylights: %s\n",
                printableLine(platformFallbackNote(choice, devices.size(), tried, candidate.fallback)).c_str());
        return;
    }
    throw Error("cannot create an OpenGL 4.5 core context (" + (tried.empty() ? std::string("no EGL display") : tried) +
                ")");
}

std::vector<EglDeviceInfo> listDevices()
{
    const EglPlatformChoice choice = eglPlatformChoice();
    std::vector<EglDeviceInfo> list;
    const std::vector<EGLDeviceEXT> devices = eglDevices(choice);
    for (std::size_t i = 0; i < devices.size(); ++i) {
        EglDeviceInfo info;
        info.index = static_cast<int>(i);
        info.software = isSoftwareDevice(choice, devices[i]);
        info.uuid = deviceUuid(choice, devices[i]);
        if (hasExtensionToken(deviceExtensions(choice, devices[i]), "EGL_EXT_device_drm"))
            if (const char* file = eglQueryDeviceStringEXT(devices[i], EGL_DRM_DEVICE_FILE_EXT))
                info.drmFile = file;
        const std::optional<Candidate> candidate = deviceCandidate(devices[i], i);
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
    // The display stays initialised for the process (EGL ends it at exit): eglTerminate
    // unloads the driver, and the next context's eglInitialize (a no-op on an initialised
    // display, EGL 1.5 §3.2) would load it again. Loading llvmpipe, a 117 MB library, was a
    // large share of a small render, paid for each render by a process that renders one image
    // after another, as the image tests do (docs/testing.md, "The suite's time").
}

}  // namespace manylights
