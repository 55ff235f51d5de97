// Debug labels, debug groups and the KHR_debug error callback.
#pragma once

#include <string>
#include <string_view>

#include "gl/GlObject.h"

namespace manylights::gl {

// Installs a synchronous debug-output callback that turns every GL error into an
// immediate abort naming the message (the call stack then points at the offending call).
// Needs a context created with the debug flag to be reliable.
void installErrorCallback();

// Aborts naming `where` if glGetError reports an error: a cheap check for the end of a test
// or a frame when no debug context is present.
void checkNoError(const char* where);

// After every allocation of GL storage (gl::Texture2D, gl::MipmappedTexture2D, gl::Buffer, the
// shadow-map arrays): throws manylights::Error "out of memory
// allocating WHAT" if the driver reported GL_OUT_OF_MEMORY, which a user meets by asking for
// an image too large for the machine; aborts on any other GL error, as checkNoError does.
void throwIfOutOfMemory(const std::string& what);
// The error throwIfOutOfMemory throws: "out of memory allocating WHAT".
[[noreturn]] void throwOutOfMemory(const std::string& what);

// Brackets a pass in debuggers and profilers (glPushDebugGroup / glPopDebugGroup).
class DebugGroup {
public:
    explicit DebugGroup(std::string_view name);
    ~DebugGroup();
    DebugGroup(const DebugGroup&) = delete;
    DebugGroup& operator=(const DebugGroup&) = delete;
};

}  // namespace manylights::gl
