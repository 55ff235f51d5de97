#include "gl/Texture.h"

#include <string>

#include "gl/Debug.h"

namespace manylights::gl {

Texture2D::Texture2D(std::string_view label, GLenum internalFormat, int width, int height)
    : GlObject(detail::createTexture(GL_TEXTURE_2D)), width_(width), height_(height), format_(internalFormat)
{
    setLabel(GL_TEXTURE, id(), label);
    glTextureStorage2D(id(), 1, internalFormat, width, height);
    throwIfOutOfMemory("the " + std::to_string(width) + "x" + std::to_string(height) + " texture '" +
                       std::string(label) + "'");
    glTextureParameteri(id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureParameteri(id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

void Texture2D::bindImage(GLuint unit, GLenum access) const
{
    counted(glBindImageTexture, unit, id(), 0, GLboolean{GL_FALSE}, 0, access, format_);
}

void Texture2D::setLinearFiltering() const
{
    glTextureParameteri(id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
}

void Texture2D::setWrap(GLenum wrap) const
{
    glTextureParameteri(id(), GL_TEXTURE_WRAP_S, static_cast<GLint>(wrap));
    glTextureParameteri(id(), GL_TEXTURE_WRAP_T, static_cast<GLint>(wrap));
}

void Texture2D::setBorderColour(const std::array<float, 4>& rgba) const
{
    glTextureParameterfv(id(), GL_TEXTURE_BORDER_COLOR, rgba.data());
}

void Texture2D::compareDepth(GLenum function) const
{
    glTextureParameteri(id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTextureParameteri(id(), GL_TEXTURE_COMPARE_FUNC, static_cast<GLint>(function));
}

void Texture2D::clearDepth(float depth) const { glClearTexImage(id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, &depth); }

void Texture2D::clearToZero() const
{
    // No data clears to zero; the format named must still match the texture's kind (an
    // integer texture takes an integer format, GL 4.5, 8.21).
    GLenum format = GL_RED;
    GLenum type = GL_FLOAT;
    switch (format_) {
    case GL_R8UI:
    case GL_R16UI:
    case GL_R32UI:
    case GL_RG32UI:
    case GL_RGBA32UI:
        format = GL_RED_INTEGER;
        type = GL_UNSIGNED_INT;
        break;
    case GL_DEPTH_COMPONENT24:
    case GL_DEPTH_COMPONENT32F: format = GL_DEPTH_COMPONENT; break;
    case GL_DEPTH24_STENCIL8:
        format = GL_DEPTH_STENCIL;
        type = GL_UNSIGNED_INT_24_8;
        break;
    default: break;
    }
    glClearTexImage(id(), 0, format, type, nullptr);
}

void Texture2D::read(GLenum format, GLenum type, std::size_t bytes, void* data) const
{
    glGetTextureImage(id(), 0, format, type, static_cast<GLsizei>(bytes), data);
}

void Texture2D::write(GLenum format, GLenum type, const void* data) const
{
    glTextureSubImage2D(id(), 0, 0, 0, width_, height_, format, type, data);
}

DepthTextureArray::DepthTextureArray(GLenum target, std::string_view label, int size, int layers)
    : GlObject(detail::createTexture(target))
{
    setLabel(GL_TEXTURE, id(), label);
    glTextureStorage3D(id(), 1, GL_DEPTH_COMPONENT24, size, size, layers);
    throwIfOutOfMemory(std::to_string(layers) + " shadow maps of " + std::to_string(size) + "x" + std::to_string(size) +
                       " ('" + std::string(label) + "')");
    glTextureParameteri(id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTextureParameteri(id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glTextureParameteri(id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    const float farthest = 1.0f;
    glClearTexImage(id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, &farthest);
}

BufferTexture::BufferTexture(std::string_view label, GLenum internalFormat, const Buffer& buffer)
    : GlObject(detail::createTexture(GL_TEXTURE_BUFFER))
{
    setLabel(GL_TEXTURE, id(), label);
    glTextureBuffer(id(), internalFormat, buffer.id());
}

}  // namespace manylights::gl
