// gl::Program: a linked shader program made from shader files with #defines and #includes
// (gl/ShaderSource.h), whose compile and link errors become manylights::Error naming the file and
// line; uniforms are set by explicit location (glProgramUniform*), never looked up by name.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gl/GlObject.h"
#include "gl/ShaderSource.h"

namespace manylights::gl {

namespace detail {
inline void deleteProgram(GLuint name) { glDeleteProgram(name); }
}  // namespace detail

struct ShaderStage {
    GLenum type;       // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, GL_COMPUTE_SHADER
    std::string file;  // path under shaders/
};

// A linked program. Uniforms use explicit `layout(location = N)` in the shaders, so they are
// set by location with glProgramUniform* and no name lookups.
class Program : public GlObject<detail::deleteProgram> {
public:
    Program() = default;
    // Throws manylights::Error with the driver's log, positions mapped to file:line, when a
    // stage fails to compile or the program fails to link.
    Program(std::string_view label, const std::vector<ShaderStage>& stages, const Defines& defines = {},
            const ShaderFileReader& reader = defaultShaderReader());

    void use() const { counted(glUseProgram, id()); }
    void set(GLint location, int value) const { counted(glProgramUniform1i, id(), location, value); }
    void set(GLint location, unsigned value) const { counted(glProgramUniform1ui, id(), location, value); }
    void set(GLint location, float value) const { counted(glProgramUniform1f, id(), location, value); }
    void set(GLint location, double value) const { counted(glProgramUniform1d, id(), location, value); }
    void set(GLint location, const glm::uvec2& value) const
    {
        counted(glProgramUniform2ui, id(), location, value.x, value.y);
    }
    void set(GLint location, const glm::vec2& value) const;
    void set(GLint location, const glm::vec3& value) const;
    void set(GLint location, const glm::vec4& value) const;
    void set(GLint location, const glm::mat3& value) const;
    void set(GLint location, const glm::mat3x2& value) const;  // GLSL mat3x2: 3 columns of 2
    void set(GLint location, const glm::mat4& value) const;
};

}  // namespace manylights::gl
