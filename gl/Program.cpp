#include "gl/Program.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <glm/gtc/type_ptr.hpp>

#include "core/AtomicFile.h"
#include "core/Error.h"

namespace manylights::gl {

namespace {

const char* stageName(GLenum type)
{
    switch (type) {
    case GL_VERTEX_SHADER: return "vertex";
    case GL_FRAGMENT_SHADER: return "fragment";
    case GL_COMPUTE_SHADER: return "compute";
    default: return "shader";
    }
}

std::string infoLog(GLuint object, bool isProgram)
{
    GLint length = 0;
    if (isProgram)
        glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
    else
        glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(length > 0 ? length : 0), '\0');
    if (isProgram)
        glGetProgramInfoLog(object, length, nullptr, log.data());
    else
        glGetShaderInfoLog(object, length, nullptr, log.data());
    while (!log.empty() && (log.back() == '\0' || log.back() == '\n'))
        log.pop_back();
    return log;
}

const char* stageExtension(GLenum type)
{
    switch (type) {
    case GL_VERTEX_SHADER: return "vert";
    case GL_FRAGMENT_SHADER: return "frag";
    default: return "comp";
    }
}

// MANYLIGHTS_SHADER_DUMP=DIR: every stage the driver compiled (includes and defines expanded;
// the tests' deliberately broken shaders fail before) is written to DIR once per distinct
// text, named after its file, so that a reference compiler can check what the renderer builds
// (scripts/check-shaders.sh, issue 30). Each file is written atomically: the test processes
// that share a dump folder run at once.
void dumpCompiledStage(const ShaderStage& stage, const std::string& text)
{
    const char* directory = std::getenv("MANYLIGHTS_SHADER_DUMP");
    if (!directory || !*directory)
        return;
    std::uint64_t hash = 14695981039346656037ull;  // FNV-1a, 64 bits: names, not security
    for (const char c : text)
        hash = (hash ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
    const std::string stem = std::filesystem::path(stage.file).stem().string();
    const std::filesystem::path path =
        std::filesystem::path(directory) / (stem + "-" + hex + "." + stageExtension(stage.type));
    if (std::filesystem::exists(path))
        return;
    std::filesystem::create_directories(directory);
    writeFileAtomically(path, "shader dump", text);
}

// Deletes the shader objects once the program is linked (or failed).
struct ShaderList {
    std::vector<GLuint> shaders;
    ~ShaderList()
    {
        for (GLuint shader : shaders)
            glDeleteShader(shader);
    }
};

}  // namespace

Program::Program(std::string_view label, const std::vector<ShaderStage>& stages, const Defines& defines,
                 const ShaderFileReader& reader)
    : GlObject(glCreateProgram())
{
    setLabel(GL_PROGRAM, id(), label);
    ShaderList compiled;
    for (const ShaderStage& stage : stages) {
        const ResolvedShader source = resolveShader(stage.file, defines, reader);
        const GLuint shader = glCreateShader(stage.type);
        compiled.shaders.push_back(shader);
        const char* text = source.text.c_str();
        glShaderSource(shader, 1, &text, nullptr);
        glCompileShader(shader);
        GLint ok = GL_FALSE;
        glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
        if (ok != GL_TRUE)
            throw Error(std::string(stageName(stage.type)) + " shader " + stage.file +
                        " failed to compile: " + mapCompileLog(infoLog(shader, false), source.files));
        dumpCompiledStage(stage, source.text);
        glAttachShader(id(), shader);
    }
    glLinkProgram(id());
    GLint ok = GL_FALSE;
    glGetProgramiv(id(), GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE)
        throw Error("program " + std::string(label) + " failed to link: " + infoLog(id(), true));
}

void Program::set(GLint location, const glm::vec2& value) const
{
    counted(glProgramUniform2fv, id(), location, 1, glm::value_ptr(value));
}
void Program::set(GLint location, const glm::vec3& value) const
{
    counted(glProgramUniform3fv, id(), location, 1, glm::value_ptr(value));
}
void Program::set(GLint location, const glm::vec4& value) const
{
    counted(glProgramUniform4fv, id(), location, 1, glm::value_ptr(value));
}
void Program::set(GLint location, const glm::mat3& value) const
{
    counted(glProgramUniformMatrix3fv, id(), location, 1, GLboolean{GL_FALSE}, glm::value_ptr(value));
}
void Program::set(GLint location, const glm::mat3x2& value) const
{
    counted(glProgramUniformMatrix3x2fv, id(), location, 1, GLboolean{GL_FALSE}, glm::value_ptr(value));
}
void Program::set(GLint location, const glm::mat4& value) const
{
    counted(glProgramUniformMatrix4fv, id(), location, 1, GLboolean{GL_FALSE}, glm::value_ptr(value));
}

}  // namespace manylights::gl
