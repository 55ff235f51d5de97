// gl::Texture2D: a single-level 2D texture for render targets and the G-buffer, owned and
// labelled (material textures with mipmaps are gl/MipmappedTexture.h); gl::DepthTextureArray:
// the layered depth textures of the local lights' shadow maps; gl::BufferTexture: a buffer's
// bytes read as texels.
#pragma once

#include <array>
#include <cstddef>
#include <string_view>

#include "gl/Buffer.h"
#include "gl/GlObject.h"

namespace manylights::gl {

namespace detail {
inline void deleteTexture(GLuint name) { glDeleteTextures(1, &name); }
// A new texture object of `target` (DSA: created, not bound).
inline GLuint createTexture(GLenum target) { return createName(glCreateTextures, target); }
}  // namespace detail

// A single-level 2D texture with immutable storage (glTextureStorage2D), nearest filtering:
// render targets and G-buffer attachments are read texel for texel, never filtered.
class Texture2D : public GlObject<detail::deleteTexture> {
public:
    Texture2D() = default;
    Texture2D(std::string_view label, GLenum internalFormat, int width, int height);

    int width() const { return width_; }
    int height() const { return height_; }
    GLenum format() const { return format_; }
    void bindUnit(GLuint unit) const { counted(glBindTextureUnit, unit, id()); }
    // Binds the texture as an image of its own format for loads and stores (`access`:
    // GL_READ_ONLY, GL_WRITE_ONLY or GL_READ_WRITE).
    void bindImage(GLuint unit, GLenum access) const;

    // Sampling: bilinear instead of nearest; what lies outside [0, 1] (GL_CLAMP_TO_EDGE, or
    // GL_CLAMP_TO_BORDER with setBorderColour's colour); a depth texture compared with the
    // reference coordinate by `function` (sampler2DShadow) instead of read.
    void setLinearFiltering() const;
    void setWrap(GLenum wrap) const;
    void setBorderColour(const std::array<float, 4>& rgba) const;
    void compareDepth(GLenum function) const;

    // Every texel to `depth` (a depth format) or to zero (any format), as a GL command.
    void clearDepth(float depth) const;
    void clearToZero() const;
    // The whole image from or to the CPU, as `format` and `type` (GL's rows, bottom to top);
    // reading waits for the commands that write it.
    void read(GLenum format, GLenum type, std::size_t bytes, void* data) const;
    void write(GLenum format, GLenum type, const void* data) const;

private:
    int width_ = 0;
    int height_ = 0;
    GLenum format_ = 0;
};

// A square 24-bit depth texture array with immutable storage: GL_TEXTURE_2D_ARRAY (one map per
// layer) or GL_TEXTURE_CUBE_MAP_ARRAY (six layers per cube), cleared to the far plane and
// sampled with depth comparison (GL_LEQUAL) and linear filtering, clamped to the edge: shadow
// maps read through sampler2DArrayShadow and samplerCubeArrayShadow. Throws manylights::Error
// when the driver is out of memory for it.
class DepthTextureArray : public GlObject<detail::deleteTexture> {
public:
    DepthTextureArray() = default;
    DepthTextureArray(GLenum target, std::string_view label, int size, int layers);

    void bindUnit(GLuint unit) const { counted(glBindTextureUnit, unit, id()); }
};

// A texture buffer: the bytes of `buffer` read as texels of `internalFormat` (texelFetch on a
// samplerBuffer). It reads the buffer as it is at each draw; the buffer must outlive it.
class BufferTexture : public GlObject<detail::deleteTexture> {
public:
    BufferTexture() = default;
    BufferTexture(std::string_view label, GLenum internalFormat, const Buffer& buffer);

    void bindUnit(GLuint unit) const { counted(glBindTextureUnit, unit, id()); }
};

}  // namespace manylights::gl
