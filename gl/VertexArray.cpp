#include "gl/VertexArray.h"

namespace manylights::gl {

VertexArray::VertexArray(std::string_view label) : GlObject(detail::createName(glCreateVertexArrays))
{
    setLabel(GL_VERTEX_ARRAY, id(), label);
}

void VertexArray::setVertexBuffer(GLuint binding, const Buffer& buffer, GLsizei stride) const
{
    glVertexArrayVertexBuffer(id(), binding, buffer.id(), 0, stride);
}

void VertexArray::setFloatAttribute(GLuint location, GLuint binding, int components, GLuint offset) const
{
    glEnableVertexArrayAttrib(id(), location);
    glVertexArrayAttribFormat(id(), location, components, GL_FLOAT, GL_FALSE, offset);
    glVertexArrayAttribBinding(id(), location, binding);
}

void VertexArray::setIndexBuffer(const Buffer& buffer) const { glVertexArrayElementBuffer(id(), buffer.id()); }

}  // namespace manylights::gl
