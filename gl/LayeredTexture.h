// A 2D array texture of float layers with a few mipmap levels, each (level, layer) written on
// its own by a compute pass (as an image) and sampled with bilinear filtering within the level a
// lookup names: the environment's prefiltered radiance (render/environment/EnvironmentLight.h),
// whose rougher layers need fewer texels than the sharper ones.
#pragma once

#include <algorithm>
#include <cstddef>
#include <string_view>

#include "gl/GlObject.h"
#include "gl/Texture.h"

namespace manylights::gl {

class LayeredTexture : public GlObject<detail::deleteTexture> {
public:
    LayeredTexture() = default;
    // Storage for `levels` mipmap levels of `layers` layers of `internalFormat`, their texels
    // undefined until written; bilinear filtering within the nearest level (lookups give whole
    // levels), repeated in both directions.
    LayeredTexture(std::string_view label, GLenum internalFormat, int width, int height, int levels, int layers);

    // Writes the whole of (`level`, `layer`) from `data` (`format`, `type`).
    void writeLayer(int level, int layer, GLenum format, GLenum type, const void* data) const;
    // Binds (`level`, `layer`) as an image2D at image `unit`.
    void bindImage(GLuint unit, int level, int layer, GLenum access) const;
    // Reads the whole of (`level`, `layer`) into `data` (`bytes` long).
    void readLayer(int level, int layer, GLenum format, GLenum type, std::size_t bytes, void* data) const;
    void setWrap(GLenum s, GLenum t) const;
    void bindUnit(GLuint unit) const { counted(glBindTextureUnit, unit, id()); }

    int levelWidth(int level) const { return std::max(width_ >> level, 1); }
    int levelHeight(int level) const { return std::max(height_ >> level, 1); }
    int width() const { return width_; }
    int height() const { return height_; }
    int levels() const { return levels_; }
    int layers() const { return layers_; }

private:
    int width_ = 0;
    int height_ = 0;
    int levels_ = 0;
    int layers_ = 0;
    GLenum format_ = 0;
};

}  // namespace manylights::gl
