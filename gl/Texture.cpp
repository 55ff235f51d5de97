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
