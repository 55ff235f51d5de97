// A sampled 2D texture with a full mipmap chain and trilinear filtering (plus anisotropic, when
// asked for and the driver has it): material maps, unlike the render targets of gl/Texture.h,
// are minified and filtered.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "gl/GlObject.h"
#include "gl/Texture.h"

namespace manylights::gl {

class MipmappedTexture2D : public GlObject<detail::deleteTexture> {
public:
    MipmappedTexture2D() = default;
    // Uploads `rgba8` (width · height · 4 bytes, rows bottom to top as GL expects) as level 0 of
    // `internalFormat` (GL_SRGB8_ALPHA8 for colour, GL_RGBA8 for data) and generates the rest.
    MipmappedTexture2D(std::string_view label, GLenum internalFormat, int width, int height,
                       std::span<const std::uint8_t> rgba8);

    // Storage for `levels` levels of `internalFormat` (a float format: an environment's radiance),
    // their texels undefined until written (writeLevel, or as an image by a compute pass); trilinear
    // filtering, repeated in both directions.
    MipmappedTexture2D(std::string_view label, GLenum internalFormat, int width, int height, int levels);

    // Writes the whole of `level` from `data` (`format`, `type`; rows bottom to top as GL expects).
    void writeLevel(int level, GLenum format, GLenum type, const void* data) const;
    // Makes the levels below the first from it (glGenerateTextureMipmap).
    void generateMipmaps() const { glGenerateTextureMipmap(id()); }
    // `level` bound to image unit `unit` for `access`.
    void bindImage(GLuint unit, int level, GLenum access) const;
    // Reads `level` back into `data` (`bytes` of `format`, `type`).
    void readLevel(int level, GLenum format, GLenum type, std::size_t bytes, void* data) const;
    // The size of `level`: each level half the one before, at least 1.
    int levelWidth(int level) const { return std::max(width_ >> level, 1); }
    int levelHeight(int level) const { return std::max(height_ >> level, 1); }

    int width() const { return width_; }
    int height() const { return height_; }
    int levels() const { return levels_; }
    GLenum format() const { return format_; }
    void bindUnit(GLuint unit) const { counted(glBindTextureUnit, unit, id()); }

    // The largest anisotropy the driver filters with: GL_MAX_TEXTURE_MAX_ANISOTROPY where it
    // has anisotropic filtering (GL 4.6 core or GL_ARB/EXT_texture_filter_anisotropic), else 1.
    static float maxAnisotropy();
    // Samples up to `anisotropy` (≥ 1, at most maxAnisotropy()) texels along the footprint's
    // long axis; 1 is plain trilinear filtering.
    void setAnisotropy(float anisotropy) const;
    // How coordinates outside [0, 1] read the image (GL_REPEAT, GL_CLAMP_TO_EDGE,
    // GL_MIRRORED_REPEAT), per axis. A texture shared by materials that wrap it differently is
    // set by each before it draws (render/scene/DrawList.cpp).
    void setWrap(GLenum s, GLenum t) const;

private:
    int width_ = 0;
    int height_ = 0;
    int levels_ = 0;
    GLenum format_ = 0;
};

// floor(log2(max(width, height))) + 1: the levels of a full chain down to 1x1.
int fullMipmapLevels(int width, int height);

}  // namespace manylights::gl
