#include "gl/Debug.h"

#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "core/Error.h"

namespace manylights::gl {

void setLabel(GLenum identifier, GLuint name, std::string_view label)
{
    glObjectLabel(identifier, name, static_cast<GLsizei>(label.size()), label.data());
}

namespace {
void GLAPIENTRY onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                               const GLchar* message, const void*)
{
    (void)severity;
    // Compile and link failures reach the caller through the info log (gl::Program throws
    // with the file and line); only API errors are fatal here.
    if (type != GL_DEBUG_TYPE_ERROR || source == GL_DEBUG_SOURCE_SHADER_COMPILER)
        return;
    // Running out of memory is the machine's limit, not a mistake in the code: the allocation
    // that failed reports it as a manylights::Error (throwIfOutOfMemory). Mesa and the vendor
    // drivers begin the message with the error's name.
    if (std::string_view(message, static_cast<std::size_t>(length)).find("GL_OUT_OF_MEMORY") != std::string_view::npos)
        return;
    std::fprintf(stderr, "manylights: GL error (id %u): %.*s\n", id, static_cast<int>(length), message);
    std::abort();
}
}  // namespace

void installErrorCallback()
{
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onDebugMessage, nullptr);
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
}

void checkNoError(const char* where)
{
    const GLenum error = glGetError();
    if (error != GL_NO_ERROR) {
        std::fprintf(stderr, "manylights: GL error 0x%04x at %s\n", error, where);
        std::abort();
    }
}

void throwIfOutOfMemory(const std::string& what)
{
    bool outOfMemory = false;
    for (GLenum error = glGetError(); error != GL_NO_ERROR; error = glGetError()) {
        if (error != GL_OUT_OF_MEMORY) {
            std::fprintf(stderr, "manylights: GL error 0x%04x allocating %s\n", error, what.c_str());
            std::abort();
        }
        outOfMemory = true;
    }
    if (outOfMemory)
        throwOutOfMemory(what);
}

void throwOutOfMemory(const std::string& what) { throw Error("out of memory allocating " + what); }

DebugGroup::DebugGroup(std::string_view name)
{
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, static_cast<GLsizei>(name.size()), name.data());
}

DebugGroup::~DebugGroup() { glPopDebugGroup(); }

}  // namespace manylights::gl
