// An OpenGL 4.5 core context without a window, through EGL.
//
// Tries, in order: the EGL device platform (EGL_EXT_platform_device: a GPU server without a
// display; hardware devices before Mesa's software device), Mesa's surfaceless platform, and
// the default display. llvmpipe on a CPU-only machine and a vendor driver on a GPU server
// both come out of the same code.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace manylights {

struct ContextOptions {
    // Creates a debug context and installs the synchronous error callback. On by default in
    // Debug builds (MANYLIGHTS_GL_DEBUG), and when the environment sets MANYLIGHTS_GL_DEBUG=1.
    bool debug = false;
    // --device N: the EGL device at index N of listDevices() instead of the first that makes a
    // context (hardware first); the constructor throws manylights::Error, naming N and how many
    // devices there are, when there is no such device.
    std::optional<int> device{};
};

// An EGL device (EGL_EXT_device_enumeration), as `manylights devices` lists it.
struct EglDeviceInfo {
    int index = 0;          // the device's place in eglQueryDevicesEXT's list: --device takes it
    std::string vendor;     // GL_VENDOR of a context on the device ("" when none could be made)
    std::string renderer;   // GL_RENDERER, the same
    std::string drmFile;    // EGL_DRM_DEVICE_FILE_EXT, where the device has one
    bool software = false;  // Mesa's software device (EGL_MESA_device_software), or a software GL_RENDERER
    std::string problem;    // why no context could be made on it ("" when one was)
};

// Every EGL device, with a context made on each to ask its vendor and renderer. Empty where
// EGL cannot enumerate devices.
// Makes and ends a context on each: call it with no HeadlessContext alive.
std::vector<EglDeviceInfo> listDevices();

// Throws manylights::Error, one line naming `index` and `count`, unless 0 <= index < count.
void checkDeviceIndex(int index, std::size_t count);

class HeadlessContext {
public:
    // Throws manylights::Error with one line saying what was tried when no context can be made.
    explicit HeadlessContext(const ContextOptions& options = {});
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
