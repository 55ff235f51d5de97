#include "render/scene/TextureCache.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "core/Error.h"
#include "core/InputFile.h"
#include "gl/Driver.h"
#include "render/output/StbDecoding.h"

namespace manylights {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& problem) { throw Error(path + ": " + problem); }

// One key per file however a scene spells its path.
std::string canonicalKey(const std::string& path)
{
    std::error_code error;
    const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, error);
    return error ? path : canonical.string();
}

}  // namespace

DecodedImage decodeImageFile(const std::string& path, int maxSide)
{
    return decodeImageMemory(path, readInputBytes(path, "texture"), maxSide);
}

DecodedImage decodeImageMemory(const std::string& name, std::span<const unsigned char> bytes, int maxSide)
{
    const StbImage pixels =
        decodeWithStb(name, bytes, "texture image", StbSamples::Bytes, 4, [&](int width, int height) {
            if (width < 1 || height < 1 || width > maxSide || height > maxSide)
                fail(name, "texture is " + std::to_string(width) + "x" + std::to_string(height) +
                               ", beyond the largest " + std::to_string(maxSide) + "x" + std::to_string(maxSide) +
                               " supported");
        });
    DecodedImage image;
    image.width = pixels.width;
    image.height = pixels.height;
    const std::size_t row = static_cast<std::size_t>(image.width) * 4;
    image.rgba.resize(row * static_cast<std::size_t>(image.height));
    // stb_image's rows run top to bottom, GL's bottom to top.
    for (std::size_t y = 0; y < static_cast<std::size_t>(image.height); ++y)
        std::copy_n(pixels.bytes() + row * y, row,
                    image.rgba.data() + row * (static_cast<std::size_t>(image.height) - 1 - y));
    return image;
}

const gl::MipmappedTexture2D& TextureCache::get(const std::string& path, TextureColourSpace space)
{
    const auto embedded =
        std::find_if(embedded_.begin(), embedded_.end(), [&](const EncodedImage& image) { return image.key == path; });
    const bool isEmbedded = embedded != embedded_.end();
    const auto key = std::make_pair(isEmbedded ? path : canonicalKey(path), space);
    if (const auto found = textures_.find(key); found != textures_.end())
        return found->second;
    const int maxSide = std::min(gl::queryInteger(GL_MAX_TEXTURE_SIZE), kMaxTextureSide);
    const DecodedImage image =
        isEmbedded ? decodeImageMemory(path, embedded->bytes, maxSide) : decodeImageFile(path, maxSide);
    const GLenum format = space == TextureColourSpace::Srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8;
    gl::MipmappedTexture2D texture("texture " + path, format, image.width, image.height, image.rgba);
    texture.setAnisotropy(anisotropy_);
    return textures_.emplace(key, std::move(texture)).first->second;
}

float resolveAnisotropy(int requested, int autoLevel)
{
    const float wanted = float(requested == kAutoAnisotropy ? autoLevel : requested);
    return std::clamp(wanted, 1.0f, gl::MipmappedTexture2D::maxAnisotropy());
}

void TextureCache::setAnisotropy(int requested)
{
    anisotropy_ = resolveAnisotropy(requested, autoAnisotropy_);
    for (const auto& [key, texture] : textures_)
        texture.setAnisotropy(anisotropy_);
}

}  // namespace manylights
