// An OpenGL 4.5 core context without a window, through EGL.
//
// Tries, in order: the EGL device platform (EGL_EXT_platform_device: a GPU server without a
// display; hardware devices before Mesa's software device), Mesa's surfaceless platform, and
// the default display. llvmpipe on a CPU-only machine and a vendor driver on a GPU server
// both come out of the same code.
#pragma once

#include <string>

namespace manylights {

struct ContextOptions {
    // Creates a debug context and installs the synchronous error callback. On by default in
    // Debug builds (MANYLIGHTS_GL_DEBUG), and when the environment sets MANYLIGHTS_GL_DEBUG=1.
    bool debug = false;
};

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
