// Material textures (docs/scene-format.md diffuse_map, specular_map, normal_map): decoded from PNG or
// JPEG by stb_image, uploaded once per (file, colour space) however many materials use them,
// with a full mipmap chain.
#pragma once

#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "gl/MipmappedTexture.h"
#include "render/driver/DriverProfile.h"
#include "scene/Scene.h"

namespace manylights {

// How a texture's 8-bit values are to be read.
enum class TextureColourSpace {
    Srgb,    // colour (diffuse, emissive): stored GL_SRGB8_ALPHA8, sampled as linear values
    Linear,  // data (normal, specular): stored GL_RGBA8, sampled as they are
};

// The largest texture side accepted whatever the driver allows: a 16384² RGBA8 image is 1 GiB
// already; beyond that a file is far more likely broken than meant.
inline constexpr int kMaxTextureSide = 16384;

// An image as 8-bit RGBA, rows bottom to top (GL's order, so uv (0, 0) is the image's lower
// left corner and +v is up: the OpenGL normal-map convention of docs/scene-format.md).
struct DecodedImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;
};

// Decodes `path`; throws manylights::Error, one line naming the file, when it cannot be read,
// is not an image stb_image decodes, is truncated, or has a side above `maxSide`.
DecodedImage decodeImageFile(const std::string& path, int maxSide);
// The same for an image already in memory (an image embedded in a model file); `name` is what
// the messages call it.
DecodedImage decodeImageMemory(const std::string& name, std::span<const unsigned char> bytes, int maxSide);

// Anisotropic filtering of material textures (--anisotropy). kAutoAnisotropy picks per
// driver profile (DriverChoices::autoAnisotropy): none (1) on a software rasteriser, where llvmpipe filters every
// anisotropic tap in software (8x cost 40% of the geometry pass on the LearnOpenGL scene, docs/performance.md),
// kHardwareAnisotropy (render/driver/DriverProfile.h) on a GPU, where the texture units do it nearly for free and
// oblique floors stay sharp.
inline constexpr int kAutoAnisotropy = 0;
inline constexpr int kMaxRequestedAnisotropy = 16;  // the largest any driver offers
// The anisotropy `requested` (kAutoAnisotropy, which means `autoLevel`, or 1 to
// kMaxRequestedAnisotropy) gives on the current GL context: clamped to what the driver filters
// with.
float resolveAnisotropy(int requested, int autoLevel);

class TextureCache {
public:
    // `embedded`: images carried in the scene (Scene::encodedImages); a path equal to one's key
    // is that image, not a file. They must outlive the cache. `autoAnisotropy` is what
    // kAutoAnisotropy means (DriverChoices::autoAnisotropy). Needs a current GL context.
    explicit TextureCache(std::span<const EncodedImage> embedded = {}, int autoAnisotropy = 1)
        : embedded_(embedded),
          autoAnisotropy_(autoAnisotropy),
          anisotropy_(resolveAnisotropy(kAutoAnisotropy, autoAnisotropy))
    {
    }

    // The texture of `path` in `space`, loaded on first request. Throws manylights::Error (see
    // decodeImageFile) for a broken file or one beyond GL_MAX_TEXTURE_SIZE or kMaxTextureSide.
    const gl::MipmappedTexture2D& get(const std::string& path, TextureColourSpace space);

    // How many textures have been loaded (each file once per colour space).
    std::size_t size() const { return textures_.size(); }

    // Filters every texture, loaded or to come, with resolveAnisotropy(requested).
    void setAnisotropy(int requested);
    // The anisotropy the textures are filtered with (1: trilinear only).
    float anisotropy() const { return anisotropy_; }

private:
    std::span<const EncodedImage> embedded_;
    int autoAnisotropy_;
    float anisotropy_;
    std::map<std::pair<std::string, TextureColourSpace>, gl::MipmappedTexture2D> textures_;
};

}  // namespace manylights
