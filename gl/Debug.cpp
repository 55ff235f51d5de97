#include "gl/Debug.h"

#include <cstdio>
#include <cstdlib>

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

DebugGroup::DebugGroup(std::string_view name)
{
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, static_cast<GLsizei>(name.size()), name.data());
}

DebugGroup::~DebugGroup() { glPopDebugGroup(); }

}  // namespace manylights::gl
