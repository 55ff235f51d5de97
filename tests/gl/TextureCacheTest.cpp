// Material textures (render/scene/TextureCache.h): one upload per (file, colour space), sRGB decoded
// to linear when sampled, a full mipmap chain, and one-line errors for files that are not
// usable images.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <unistd.h>

#include <stb/stb_image_write.h>

#include "GlContextTest.h"
#include "core/Error.h"
#include "gl/Buffer.h"
#include "gl/Driver.h"
#include "gl/Program.h"
#include "render/scene/GpuScene.h"
#include "render/scene/TextureCache.h"

namespace manylights {
namespace {

namespace fs = std::filesystem;

class TextureCacheTest : public GlContextTest {
protected:
    void SetUp() override
    {
        dir_ = fs::temp_directory_path() / ("manylights-texture-test-" + std::to_string(::getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override
    {
        fs::remove_all(dir_);
        GlContextTest::TearDown();
    }
    // Writes an RGB PNG of `width` × `height` texels, rows top to bottom.
    std::string writePng(const std::string& name, int width, int height, const std::vector<unsigned char>& rgb)
    {
        const std::string path = (dir_ / name).string();
        EXPECT_NE(stbi_write_png(path.c_str(), width, height, 3, rgb.data(), width * 3), 0);
        return path;
    }
    std::string writeBytes(const std::string& name, const std::string& bytes)
    {
        const std::string path = (dir_ / name).string();
        std::ofstream(path, std::ios::binary) << bytes;
        return path;
    }
    fs::path dir_;
};

// Samples `texture` at the centre of the unit square (bilinear over a constant image returns
// its value) with texture(), i.e. with the sRGB decode a material lookup gets.
glm::vec4 sampleCentre(const gl::MipmappedTexture2D& texture)
{
    const std::map<std::string, std::string> files = {{"sample.comp",
                                                       "#version 450 core\nlayout(local_size_x = 1) in;\n"
                                                       "layout(binding = 6) uniform sampler2D map;\n"
                                                       "layout(std430, binding = 0) buffer Out { vec4 value; };\n"
                                                       "void main() { value = textureLod(map, vec2(0.5), 0.0); }\n"}};
    const gl::ShaderFileReader reader = [&files](const std::string& name) -> std::optional<std::string> {
        const auto found = files.find(name);
        return found == files.end() ? std::nullopt : std::optional<std::string>(found->second);
    };
    gl::Program program("sample texture", {{GL_COMPUTE_SHADER, "sample.comp"}}, {}, reader);
    const glm::vec4 zero(0.0f);
    gl::Buffer out("sampled value", sizeof(glm::vec4), &zero);
    out.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
    texture.bindUnit(6);
    program.use();
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glm::vec4 value(0.0f);
    glGetNamedBufferSubData(out.id(), 0, sizeof value, &value);
    return value;
}

TEST_F(TextureCacheTest, SharedTextureIsLoadedOncePerColourSpace)
{
    const std::string path = writePng("shared.png", 2, 2, std::vector<unsigned char>(12, 200));
    Scene scene;
    Material a;
    a.diffuseMap = path;
    Material b;
    b.diffuseMap = (dir_ / "." / "shared.png").string();  // another spelling of the same file
    b.normalMap = path;                                   // the same file as data: a second, linear texture
    Material c;
    c.specularMap = path;  // data again: shares b's linear texture
    scene.materials = {a, b, c, Material{}};
    const GpuScene gpuScene(scene, {}, resolveDriverChoices({.profile = DriverProfile::Auto}));
    EXPECT_EQ(gpuScene.textures().size(), 2u);
}

TEST_F(TextureCacheTest, SrgbTexelSamplesAsItsLinearValue)
{
    // sRGB 8-bit 128 is linear ((128/255 + 0.055) / 1.055)^2.4 = 0.2158605; the same byte as
    // data is 128/255 = 0.5019608.
    const std::string path = writePng("grey128.png", 1, 1, {128, 128, 128});
    TextureCache cache;
    const glm::vec4 colour = sampleCentre(cache.get(path, TextureColourSpace::Srgb));
    const glm::vec4 data = sampleCentre(cache.get(path, TextureColourSpace::Linear));
    const double linear = std::pow((128.0 / 255.0 + 0.055) / 1.055, 2.4);
    // GL allows the sRGB decode an error of about 1 part in 2^8 of the result's range near 0
    // and usually does it exactly through a table: 1e-3 separates it clearly from 0.502.
    EXPECT_NEAR(colour.r, linear, 1e-3);
    EXPECT_NEAR(colour.g, linear, 1e-3);
    EXPECT_NEAR(colour.b, linear, 1e-3);
    EXPECT_EQ(colour.a, 1.0f);
    EXPECT_NEAR(data.r, 128.0 / 255.0, 1e-6);
}

TEST_F(TextureCacheTest, FullMipmapChainIsGeneratedAndFiltered)
{
    // 8x2 texels: the full chain is 8x2, 4x1, 2x1, 1x1. Left half black, right half white:
    // the 1x1 level is their average, which only a generated chain holds.
    std::vector<unsigned char> rgb;
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 8; ++x)
            for (int c = 0; c < 3; ++c)
                rgb.push_back(x < 4 ? 0 : 255);
    const std::string path = writePng("halves.png", 8, 2, rgb);
    TextureCache cache;
    const gl::MipmappedTexture2D& texture = cache.get(path, TextureColourSpace::Linear);
    EXPECT_EQ(texture.levels(), 4);
    EXPECT_EQ(gl::fullMipmapLevels(8, 2), 4);
    GLint immutableLevels = 0;
    glGetTextureParameteriv(texture.id(), GL_TEXTURE_IMMUTABLE_LEVELS, &immutableLevels);
    EXPECT_EQ(immutableLevels, 4);
    GLint minFilter = 0;
    glGetTextureParameteriv(texture.id(), GL_TEXTURE_MIN_FILTER, &minFilter);
    EXPECT_EQ(minFilter, GL_LINEAR_MIPMAP_LINEAR);
    GLint lastWidth = 0;
    GLint lastHeight = 0;
    glGetTextureLevelParameteriv(texture.id(), 3, GL_TEXTURE_WIDTH, &lastWidth);
    glGetTextureLevelParameteriv(texture.id(), 3, GL_TEXTURE_HEIGHT, &lastHeight);
    EXPECT_EQ(lastWidth, 1);
    EXPECT_EQ(lastHeight, 1);
    unsigned char last[4] = {};
    glGetTextureImage(texture.id(), 3, GL_RGBA, GL_UNSIGNED_BYTE, sizeof last, last);
    EXPECT_NEAR(last[0], 127.5, 1.0);
    EXPECT_EQ(last[3], 255);
}

TEST_F(TextureCacheTest, AnisotropyIsSetOnLoadedAndLaterTextures)
{
    const float maximum = gl::MipmappedTexture2D::maxAnisotropy();
    if (maximum < 4.0f)
        GTEST_SKIP() << "this driver filters with at most " << maximum << "x anisotropy";
    const auto anisotropyOf = [](const gl::MipmappedTexture2D& texture) {
        GLfloat value = 0.0f;
        glGetTextureParameterfv(texture.id(), GL_TEXTURE_MAX_ANISOTROPY, &value);
        return value;
    };
    // `auto` is what the driver profile says: none for software, 8x for a GPU.
    for (const DriverProfile profile : {DriverProfile::Software, DriverProfile::Gpu}) {
        TextureCache cache({}, resolveDriverChoices({.profile = profile}).autoAnisotropy);
        const gl::MipmappedTexture2D& texture =
            cache.get(writePng("auto.png", 2, 2, std::vector<unsigned char>(12, 9)), TextureColourSpace::Linear);
        EXPECT_EQ(anisotropyOf(texture),
                  profile == DriverProfile::Software ? 1.0f : std::min(maximum, float(kHardwareAnisotropy)));
    }
    TextureCache cache;
    const gl::MipmappedTexture2D& first =
        cache.get(writePng("a.png", 2, 2, std::vector<unsigned char>(12, 9)), TextureColourSpace::Linear);
    EXPECT_EQ(anisotropyOf(first), 1.0f);
    cache.setAnisotropy(4);
    EXPECT_EQ(cache.anisotropy(), 4.0f);
    EXPECT_EQ(anisotropyOf(first), 4.0f);
    const gl::MipmappedTexture2D& second =
        cache.get(writePng("b.png", 2, 2, std::vector<unsigned char>(12, 9)), TextureColourSpace::Linear);
    EXPECT_EQ(anisotropyOf(second), 4.0f);
    // Beyond the driver's maximum: its maximum.
    cache.setAnisotropy(kMaxRequestedAnisotropy);
    EXPECT_EQ(anisotropyOf(second), std::min(maximum, float(kMaxRequestedAnisotropy)));
    cache.setAnisotropy(1);
    EXPECT_EQ(anisotropyOf(first), 1.0f);
}

TEST(Driver, SoftwareRenderersAreRecognisedByName)
{
    EXPECT_TRUE(gl::isSoftwareRendererName("llvmpipe (LLVM 15.0.6, 256 bits)"));
    EXPECT_TRUE(gl::isSoftwareRendererName("softpipe"));
    EXPECT_FALSE(gl::isSoftwareRendererName("NVIDIA H200/PCIe/SSE2"));
    EXPECT_FALSE(gl::isSoftwareRendererName("AMD Radeon RX 7900 XTX (radeonsi, navi31, LLVM 15.0.7, DRM 3.54)"));
}

TEST_F(TextureCacheTest, BrokenFilesAreOneLineErrorsNamingTheFile)
{
    const std::string valid = writePng("valid.png", 16, 16, std::vector<unsigned char>(16 * 16 * 3, 90));
    std::ifstream in(valid, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // A PNG whose header (IHDR) claims 17000 x 17000 (above kMaxTextureSide; stb_image itself
    // refuses headers of more than 2^30 bytes): refused from the header, before decoding.
    std::string huge = bytes.substr(0, 33);
    const unsigned char side[4] = {0x00, 0x00, 0x42, 0x68};  // 17000, big-endian
    huge.replace(16, 4, reinterpret_cast<const char*>(side), 4);
    huge.replace(20, 4, reinterpret_cast<const char*>(side), 4);
    const std::string cases[][2] = {
        {writeBytes("text.png", "this is not an image\n"), "not a texture image"},
        {writeBytes("truncated.png", bytes.substr(0, bytes.size() / 2)), "truncated texture image"},
        {writeBytes("huge.png", huge), "17000x17000"},
        {(dir_ / "absent.png").string(), "cannot open"},
    };
    for (const auto& [path, problem] : cases) {
        TextureCache cache;
        try {
            cache.get(path, TextureColourSpace::Srgb);
            ADD_FAILURE() << path << " was accepted";
        } catch (const Error& e) {
            const std::string message = e.what();
            EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
            EXPECT_NE(message.find(problem), std::string::npos) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        }
        EXPECT_EQ(cache.size(), 0u);
    }
}

}  // namespace
}  // namespace manylights
