// Image files cut short (issue 48, docs/scene-format.md "Image files cut short"): every texture
// format stb_image writes (PNG, JPEG, BMP, TGA, and so every format the loaders share) and both
// environment map formats (Radiance .hdr, run-length and flat, and OpenEXR), each written
// whole, read back whole, then cut at several points from inside the header to the last byte:
// each cut is one error line that names the file and says it is truncated. No GL: the
// decoders are the render layer's, which this tier links.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include <unistd.h>

#include <stb/stb_image_write.h>

#include "core/Error.h"
#include "render/environment/EnvironmentFiles.h"
#include "render/output/ExrFile.h"
#include "render/scene/TextureCache.h"

namespace manylights {
namespace {

namespace fs = std::filesystem;

constexpr int kImageWidth = 32;
constexpr int kImageHeight = 16;

void appendTo(void* context, void* data, int size)
{
    static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}

// A texture with detail in every block (a JPEG of a flat colour would be almost all header).
std::vector<unsigned char> textureTexels()
{
    std::vector<unsigned char> rgb;
    for (int y = 0; y < kImageHeight; ++y)
        for (int x = 0; x < kImageWidth; ++x)
            for (int c = 0; c < 3; ++c)
                rgb.push_back(static_cast<unsigned char>((x * 37 + y * 91 + c * 53 + x * y * 7) % 256));
    return rgb;
}

// A sky map with a varied radiance per texel, 2:1 as environment maps must be.
Image radianceMap(int width)
{
    Image map{width, width / 2, {}};
    for (int i = 0; i < width * map.height * 3; ++i)
        map.rgb.push_back(0.1f + static_cast<float>((i * 29) % 97) / 10.0f);
    return map;
}

std::string encodedWithStb(const std::function<int(std::string*)>& write)
{
    std::string bytes;
    EXPECT_NE(write(&bytes), 0);
    return bytes;
}

// Cut points from inside the header (about 40 bytes in; a PNG's first chunk ends at 33) to
// the last byte: a fifth, half, four fifths and the end markers' bytes.
std::vector<std::size_t> cutPoints(std::size_t size)
{
    return {40, size / 5, size / 2, size * 4 / 5, size - 12, size - 4, size - 2, size - 1};
}

void expectTruncatedError(const std::function<void()>& load, const std::string& name, std::size_t cut)
{
    try {
        load();
        ADD_FAILURE() << name << " cut to " << cut << " bytes was accepted";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind(name + ": ", 0), 0u) << message;
        // The problem, right after the name, says the file is cut short.
        EXPECT_EQ(message.compare(name.size() + 2, 10, "truncated "), 0) << "cut to " << cut << ": " << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

struct TextureFormat {
    std::string name;
    std::function<int(std::string*)> write;
};

TEST(TruncatedImages, TexturesCutAnywhereAreRefusedAsTruncated)
{
    const std::vector<unsigned char> rgb = textureTexels();
    const std::vector<TextureFormat> formats = {
        {"texture.png",
         [&](std::string* out) {
             return stbi_write_png_to_func(appendTo, out, kImageWidth, kImageHeight, 3, rgb.data(), 0);
         }},
        {"texture.jpg",
         [&](std::string* out) {
             return stbi_write_jpg_to_func(appendTo, out, kImageWidth, kImageHeight, 3, rgb.data(), 90);
         }},
        {"texture.bmp",
         [&](std::string* out) {
             return stbi_write_bmp_to_func(appendTo, out, kImageWidth, kImageHeight, 3, rgb.data());
         }},
        {"texture.tga",
         [&](std::string* out) {
             return stbi_write_tga_to_func(appendTo, out, kImageWidth, kImageHeight, 3, rgb.data());
         }},
    };
    for (const TextureFormat& format : formats) {
        const std::string whole = encodedWithStb(format.write);
        ASSERT_GT(whole.size(), 200u) << format.name;
        const auto bytesOf = [](const std::string& text) {
            return std::span(reinterpret_cast<const unsigned char*>(text.data()), text.size());
        };
        // Whole, it decodes: the cuts below are refused for being cut, not for their format.
        const DecodedImage decoded = decodeImageMemory(format.name, bytesOf(whole), kMaxTextureSide);
        EXPECT_EQ(decoded.width, kImageWidth) << format.name;
        EXPECT_EQ(decoded.height, kImageHeight) << format.name;
        for (const std::size_t cut : cutPoints(whole.size())) {
            const std::string part = whole.substr(0, cut);
            expectTruncatedError([&] { decodeImageMemory(format.name, bytesOf(part), kMaxTextureSide); }, format.name,
                                 cut);
        }
    }
}

TEST(TruncatedImages, BytesAfterTheEndMarkerAreAccepted)
{
    // libpng ignores what follows a PNG's IEND, and JPEG readers what follows the end-of-image
    // marker (cameras append data there): so does the loader.
    const std::vector<unsigned char> rgb = textureTexels();
    const std::vector<TextureFormat> formats = {
        {"padded.png",
         [&](std::string* out) {
             return stbi_write_png_to_func(appendTo, out, kImageWidth, kImageHeight, 3, rgb.data(), 0);
         }},
        {"padded.jpg",
         [&](std::string* out) {
             return stbi_write_jpg_to_func(appendTo, out, kImageWidth, kImageHeight, 3, rgb.data(), 90);
         }},
    };
    for (const TextureFormat& format : formats) {
        const std::string padded = encodedWithStb(format.write) + "trailing bytes";
        const DecodedImage decoded = decodeImageMemory(
            format.name, std::span(reinterpret_cast<const unsigned char*>(padded.data()), padded.size()),
            kMaxTextureSide);
        EXPECT_EQ(decoded.width, kImageWidth) << format.name;
        EXPECT_EQ(decoded.height, kImageHeight) << format.name;
    }
}

class TruncatedEnvironmentMaps : public ::testing::Test {
protected:
    void SetUp() override
    {
        dir_ = fs::temp_directory_path() / ("manylights-cut-files-test-" + std::to_string(::getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string write(const std::string& name, const std::string& bytes)
    {
        const std::string path = (dir_ / name).string();
        std::ofstream(path, std::ios::binary) << bytes;
        return path;
    }

    // Loads `whole` as `name` and checks it; then each cut is refused as truncated.
    void expectCutsRefused(const std::string& name, const std::string& whole, const Image& map, float tolerance)
    {
        const EnvironmentImage loaded = loadEnvironmentImage(write(name, whole), kMaxEnvironmentWidth);
        ASSERT_EQ(loaded.width, map.width) << name;
        ASSERT_EQ(loaded.height, map.height) << name;
        for (std::size_t i = 0; i < loaded.radiance.size(); ++i) {
            const float largest = std::max({map.rgb[i * 3], map.rgb[i * 3 + 1], map.rgb[i * 3 + 2]});
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(loaded.radiance[i][c], map.rgb[i * 3 + c], tolerance * largest) << name;
        }
        for (const std::size_t cut : cutPoints(whole.size())) {
            const std::string path = write(name, whole.substr(0, cut));
            expectTruncatedError([&] { loadEnvironmentImage(path, kMaxEnvironmentWidth); }, path, cut);
        }
    }

    fs::path dir_;
};

TEST_F(TruncatedEnvironmentMaps, RadianceFilesCutAnywhereAreRefusedAsTruncated)
{
    // Radiance's exponent is shared by a texel's channels and its mantissas have 8 bits: each
    // channel within 1/128 of the texel's largest (stb_image_write rounds down).
    constexpr float kRgbeTolerance = 1.0f / 128.0f;
    // 64 wide: stb_image_write run-length encodes scan lines of 8 to 32767 texels; 4 wide is
    // written flat, 4 bytes a texel, which stb_image reads another way.
    for (const int width : {64, 4}) {
        const Image map = radianceMap(width);
        const std::string whole = encodedWithStb([&](std::string* out) {
            return stbi_write_hdr_to_func(appendTo, out, map.width, map.height, 3, map.rgb.data());
        });
        expectCutsRefused("sky" + std::to_string(width) + ".hdr", whole, map, kRgbeTolerance);
    }
}

TEST_F(TruncatedEnvironmentMaps, OpenExrFilesCutAnywhereAreRefusedAsTruncated)
{
    const Image map = radianceMap(64);
    const std::string whole = encodeExr({ExrLayer{"", {"R", "G", "B"}, map}}, ExrPixels::Float);
    expectCutsRefused("sky.exr", whole, map, 0.0f);
}

}  // namespace
}  // namespace manylights
