// An OpenGL 4.5 core context without a window, through EGL.
//
// Tries, in order: the EGL device platform (EGL_EXT_platform_device: a GPU server without a
// display; hardware devices before Mesa's software device), Mesa's surfaceless platform, and
// the default display. llvmpipe on a CPU-only machine and a vendor driver on a GPU server
// both come out of the same code. platform/EglChoice.h decides from the client extensions
// which platforms EGL offers (issue 40: glvnd names device enumeration EGL_EXT_device_base).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "platform/EglChoice.h"

namespace manylights {

struct ContextOptions {
    // Creates a debug context and installs the synchronous error callback. On by default in
    // Debug builds (MANYLIGHTS_GL_DEBUG), and when the environment sets MANYLIGHTS_GL_DEBUG=1.
    bool debug = false;
    // --device N|UUID: the EGL device at index N of listDevices(), or the one with that UUID,
    // instead of the first that makes a context (hardware first); the constructor throws
    // manylights::Error, one line as selectDevice's, when there is no such device.
    std::optional<DeviceSelector> device{};
};

// An EGL device (EGL_EXT_device_enumeration), as `manylights devices` lists it.
struct EglDeviceInfo {
    int index = 0;                   // the device's place in eglQueryDevicesEXT's list: --device takes it
    std::string vendor;              // GL_VENDOR of a context on the device ("" when none could be made)
    std::string renderer;            // GL_RENDERER, the same
    std::string drmFile;             // EGL_DRM_DEVICE_FILE_EXT, where the device has one
    std::optional<DeviceUuid> uuid;  // EGL_DEVICE_UUID_EXT, where it has EGL_EXT_device_persistent_id
    bool software = false;           // Mesa's software device (EGL_MESA_device_software), or a software GL_RENDERER
    std::string problem;             // why no context could be made on it ("" when one was)
};

// What this process's EGL library offers (chooseEglPlatforms of its client extensions).
EglPlatformChoice eglPlatformChoice();

// Every EGL device, with a context made on each to ask its vendor and renderer. Empty where
// EGL cannot enumerate devices (eglPlatformChoice() says why).
// Makes and ends a context on each: call it with no HeadlessContext alive.
std::vector<EglDeviceInfo> listDevices();

// The place in `devices` (listDevices()) of the device `selector` names. Throws
// manylights::Error as selectDevice does.
std::size_t selectListedDevice(const DeviceSelector& selector, const std::vector<EglDeviceInfo>& devices);

class HeadlessContext {
public:
    // Throws manylights::Error with one line saying what was tried when no context can be made.
    // Where the context is not on an EGL device although no --device was given, says on stderr
    // why and through which platform it renders, once per process (platformFallbackNote): a GPU
    // server that falls back to llvmpipe is otherwise only seen in the timings.
    explicit HeadlessContext(const ContextOptions& options = {});
    // Ends the context but leaves its EGL display initialised for the next one (EGL ends it at
    // exit): terminating it would unload the driver, for the next context to load again.
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    // "GL_RENDERER (GL_VERSION) via <platform>": for logs and --stats.
    const std::string& description() const { return description_; }

private:
    void* display_ = nullptr;
    void* context_ = nullptr;
    std::string description_;
};

// The debug default of this build and environment (see ContextOptions::debug).
bool defaultDebugContext();

}  // namespace manylights
