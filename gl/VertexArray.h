// gl::VertexArray: a vertex array object (DSA): its vertex buffer bindings, attribute formats and
// index buffer, owned and labelled.
#pragma once

#include <string_view>

#include "gl/Buffer.h"
#include "gl/GlObject.h"

namespace manylights::gl {

namespace detail {
inline void deleteVertexArray(GLuint name) { glDeleteVertexArrays(1, &name); }
}  // namespace detail

class VertexArray : public GlObject<detail::deleteVertexArray> {
public:
    // An empty vertex array: enough for draws that build their vertices from gl_VertexID.
    explicit VertexArray(std::string_view label);
    VertexArray() = default;

    // Attribute `location` reads `components` floats at `offset` inside each `stride`-byte
    // vertex of binding point `binding`.
    void setVertexBuffer(GLuint binding, const Buffer& buffer, GLsizei stride) const;
    void setFloatAttribute(GLuint location, GLuint binding, int components, GLuint offset) const;
    void setIndexBuffer(const Buffer& buffer) const;
    void bind() const { counted(glBindVertexArray, id()); }
};

}  // namespace manylights::gl
