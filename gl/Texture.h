// gl::Texture2D: a single-level 2D texture for render targets and the G-buffer, owned and
// labelled (material textures with mipmaps are gl/MipmappedTexture.h).
#pragma once

#include <string_view>

#include "gl/GlObject.h"

namespace manylights::gl {

namespace detail {
inline void deleteTexture(GLuint name) { glDeleteTextures(1, &name); }
// A new texture object of `target` (DSA: created, not bound).
inline GLuint createTexture(GLenum target)
{
    GLuint name = 0;
    glCreateTextures(target, 1, &name);
    return name;
}
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
    void bindUnit(GLuint unit) const { glBindTextureUnit(unit, id()); }

private:
    int width_ = 0;
    int height_ = 0;
    GLenum format_ = 0;
};

}  // namespace manylights::gl
