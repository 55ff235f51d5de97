#include "render/environment/EnvironmentFiles.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>

// Debian's libstb ships stb_image compiled (-lstb): no STB_IMAGE_IMPLEMENTATION here.
#include <stb/stb_image.h>

#include "core/Error.h"
#include "core/InputFile.h"
#include "render/output/ExrFile.h"
#include "render/output/StbDecoding.h"

namespace manylights {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& problem) { throw Error(path + ": " + problem); }

std::string lowerExtension(const std::string& path)
{
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

void checkSize(const std::string& path, int width, int height, int maxTextureSize)
{
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    if (width < 2 || height < 1 || width != 2 * height)
        fail(path, "an environment map must be equirectangular, twice as wide as high, got " + size);
    const int maxWidth = std::min(kMaxEnvironmentWidth, maxTextureSize);
    if (width > maxWidth)
        fail(path, "environment map is " + size + ", beyond the largest " + std::to_string(maxWidth) + "x" +
                       std::to_string(maxWidth / 2) + " supported");
}

EnvironmentImage decodeHdr(const std::string& path, int maxTextureSize)
{
    // The file's bytes only while stb_image decodes them: with the decoded pixels and their
    // copy below, a large map would otherwise hold three copies at once.
    const StbImage pixels = [&] {
        const std::vector<unsigned char> bytes = readInputBytes(path, "environment map");
        // stb_image would read a PNG or JPEG as radiance too, through a gamma curve: only a
        // Radiance file holds radiance. (readInputBytes refuses files beyond an int's range.)
        if (!stbi_is_hdr_from_memory(bytes.data(), static_cast<int>(bytes.size())))
            fail(path, "not a Radiance .hdr image");
        return decodeWithStb(path, bytes, "Radiance .hdr image", StbSamples::Floats, 3,
                             [&](int width, int height) { checkSize(path, width, height, maxTextureSize); });
    }();
    EnvironmentImage map{.width = pixels.width, .height = pixels.height, .radiance = {}};
    map.radiance.resize(static_cast<std::size_t>(map.width) * map.height);
    // stb_image's rows run top to bottom, as the map's.
    const float* rgb = pixels.floats();
    for (std::size_t i = 0; i < map.radiance.size(); ++i)
        map.radiance[i] = glm::vec3(rgb[i * 3], rgb[i * 3 + 1], rgb[i * 3 + 2]);
    return map;
}

EnvironmentImage decodeExr(const std::string& path, int maxTextureSize)
{
    // OpenEXR reports a missing file in its own words; this names it as every other input.
    readInputBytes(path, "environment map");
    const Image image = readExrLayer(path, "", {"R", "G", "B"});
    checkSize(path, image.width, image.height, maxTextureSize);
    EnvironmentImage map{.width = image.width, .height = image.height, .radiance = {}};
    map.radiance.resize(static_cast<std::size_t>(image.width) * image.height);
    // Image's rows run top to bottom (the EXR's data window from its top), as the map's.
    for (std::size_t i = 0; i < map.radiance.size(); ++i)
        map.radiance[i] = glm::vec3(image.rgb[i * 3], image.rgb[i * 3 + 1], image.rgb[i * 3 + 2]);
    return map;
}

}  // namespace

EnvironmentImage loadEnvironmentImage(const std::string& map, int maxTextureSize)
{
    if (map == kStudioEnvironment)
        return studioEnvironment(kStudioEnvironmentHeight);
    const std::string extension = lowerExtension(map);
    if (extension != ".hdr" && extension != ".exr")
        fail(map, "an environment map must be a .hdr or .exr file");
    EnvironmentImage image = extension == ".hdr" ? decodeHdr(map, maxTextureSize) : decodeExr(map, maxTextureSize);
    for (std::size_t i = 0; i < image.radiance.size(); ++i) {
        const glm::vec3& texel = image.radiance[i];
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(texel[c]) || texel[c] < 0.0f)
                fail(map, "texel (" + std::to_string(i % static_cast<std::size_t>(image.width)) + ", " +
                              std::to_string(i / static_cast<std::size_t>(image.width)) +
                              ") is not a radiance (negative or not finite)");
    }
    return image;
}

}  // namespace manylights
