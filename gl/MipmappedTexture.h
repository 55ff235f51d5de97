// A sampled 2D texture with a full mipmap chain and trilinear (plus anisotropic, where the
// driver has it) filtering: material maps, unlike the render targets of gl/Texture.h, are
// minified and filtered.
#pragma once

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

    int width() const { return width_; }
    int height() const { return height_; }
    int levels() const { return levels_; }
    GLenum format() const { return format_; }
    void bindUnit(GLuint unit) const { glBindTextureUnit(unit, id()); }

    // Anisotropic filtering applied to material textures where the driver supports it
    // (GL 4.6 core or GL_ARB/EXT_texture_filter_anisotropic): up to this, clamped to the
    // driver's maximum. 8 keeps oblique floors sharp at a small cost.
    static constexpr float kMaxAnisotropy = 8.0f;
    // The anisotropy actually set (1 where the driver has no anisotropic filtering).
    static float anisotropy();

private:
    int width_ = 0;
    int height_ = 0;
    int levels_ = 0;
    GLenum format_ = 0;
};

// floor(log2(max(width, height))) + 1: the levels of a full chain down to 1x1.
int fullMipmapLevels(int width, int height);

}  // namespace manylights::gl
