#include "gl/LayeredTexture.h"

#include <string>

#include "gl/Debug.h"

namespace manylights::gl {

LayeredTexture::LayeredTexture(std::string_view label, GLenum internalFormat, int width, int height, int levels,
                               int layers)
    : GlObject(detail::createTexture(GL_TEXTURE_2D_ARRAY)),
      width_(width),
      height_(height),
      levels_(levels),
      layers_(layers),
      format_(internalFormat)
{
    setLabel(GL_TEXTURE, id(), label);
    glTextureStorage3D(id(), levels_, internalFormat, width, height, layers);
    throwIfOutOfMemory("the " + std::to_string(width) + "x" + std::to_string(height) + "x" + std::to_string(layers) +
                       " texture array '" + std::string(label) + "'");
    glTextureParameteri(id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
    glTextureParameteri(id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
}

void LayeredTexture::writeLayer(int level, int layer, GLenum format, GLenum type, const void* data) const
{
    glTextureSubImage3D(id(), level, 0, 0, layer, levelWidth(level), levelHeight(level), 1, format, type, data);
}

void LayeredTexture::bindImage(GLuint unit, int level, int layer, GLenum access) const
{
    glBindImageTexture(unit, id(), level, GL_FALSE, layer, access, format_);
}

void LayeredTexture::readLayer(int level, int layer, GLenum format, GLenum type, std::size_t bytes, void* data) const
{
    glGetTextureSubImage(id(), level, 0, 0, layer, levelWidth(level), levelHeight(level), 1, format, type,
                         static_cast<GLsizei>(bytes), data);
}

void LayeredTexture::setWrap(GLenum s, GLenum t) const
{
    glTextureParameteri(id(), GL_TEXTURE_WRAP_S, static_cast<GLint>(s));
    glTextureParameteri(id(), GL_TEXTURE_WRAP_T, static_cast<GLint>(t));
}

}  // namespace manylights::gl
