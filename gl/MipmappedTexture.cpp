#include "gl/MipmappedTexture.h"

#include <algorithm>
#include <string>

#include "gl/Debug.h"

namespace manylights::gl {

int fullMipmapLevels(int width, int height)
{
    int levels = 1;
    for (int size = std::max(width, height); size > 1; size /= 2)
        ++levels;
    return levels;
}

float MipmappedTexture2D::maxAnisotropy()
{
    // GL_TEXTURE_MAX_ANISOTROPY (0x84FE) is the same enum in GL 4.6 core, ARB and EXT.
    const bool supported = epoxy_gl_version() >= 46 || epoxy_has_gl_extension("GL_ARB_texture_filter_anisotropic") ||
                           epoxy_has_gl_extension("GL_EXT_texture_filter_anisotropic");
    if (!supported)
        return 1.0f;
    GLfloat maximum = 1.0f;
    glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY, &maximum);
    return std::max(maximum, 1.0f);
}

void MipmappedTexture2D::setAnisotropy(float anisotropy) const
{
    // Without the extension the parameter does not exist (setting it would be a GL error), and
    // 1 is what the texture filters with anyway.
    if (const float maximum = maxAnisotropy(); maximum > 1.0f)
        glTextureParameterf(id(), GL_TEXTURE_MAX_ANISOTROPY, std::clamp(anisotropy, 1.0f, maximum));
}

void MipmappedTexture2D::setWrap(GLenum s, GLenum t) const
{
    glTextureParameteri(id(), GL_TEXTURE_WRAP_S, static_cast<GLint>(s));
    glTextureParameteri(id(), GL_TEXTURE_WRAP_T, static_cast<GLint>(t));
}

MipmappedTexture2D::MipmappedTexture2D(std::string_view label, GLenum internalFormat, int width, int height,
                                       std::span<const std::uint8_t> rgba8)
    : MipmappedTexture2D(label, internalFormat, width, height, fullMipmapLevels(width, height))
{
    // Rows of 4-byte texels: any width is aligned, whatever GL_UNPACK_ALIGNMENT says.
    glTextureSubImage2D(id(), 0, 0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba8.data());
    // For sRGB storage GL recommends (but does not require) filtering the levels in linear
    // space; Mesa and the vendor drivers do, so colour maps do not darken when minified.
    glGenerateTextureMipmap(id());
}

MipmappedTexture2D::MipmappedTexture2D(std::string_view label, GLenum internalFormat, int width, int height, int levels)
    : GlObject(detail::createTexture(GL_TEXTURE_2D)),
      width_(width),
      height_(height),
      levels_(levels),
      format_(internalFormat)
{
    setLabel(GL_TEXTURE, id(), label);
    glTextureStorage2D(id(), levels_, internalFormat, width, height);
    throwIfOutOfMemory("the " + std::to_string(width) + "x" + std::to_string(height) + " texture '" +
                       std::string(label) + "'");
    glTextureParameteri(id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(id(), GL_TEXTURE_WRAP_T, GL_REPEAT);
}

void MipmappedTexture2D::writeLevel(int level, GLenum format, GLenum type, const void* data) const
{
    // Rows of floats are 4-byte aligned, whatever their width.
    glTextureSubImage2D(id(), level, 0, 0, levelWidth(level), levelHeight(level), format, type, data);
}

void MipmappedTexture2D::bindImage(GLuint unit, int level, GLenum access) const
{
    glBindImageTexture(unit, id(), level, GL_FALSE, 0, access, format_);
}

void MipmappedTexture2D::readLevel(int level, GLenum format, GLenum type, std::size_t bytes, void* data) const
{
    glGetTextureImage(id(), level, format, type, static_cast<GLsizei>(bytes), data);
}

}  // namespace manylights::gl
