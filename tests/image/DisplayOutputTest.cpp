// The display path and the scene-referred outputs through the command line
// (docs/display.md): the default PNG stays the contract's plain clamp; tone mapping, sRGB
// and FXAA change only 8-bit outputs, after lighting, so every technique still matches
// forward there; --supersample box-filters in linear light; EXR files hold the PFM's values
// (bit-exact as float, within half precision as half) and, with --aovs, every G-buffer view
// as a layer equal to that view's PFM.
#include <gtest/gtest.h>

#include <stb/stb_image.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "TestSupport.h"
#include "core/Error.h"
#include "render/ExrFile.h"
#include "render/Image.h"

namespace manylights {
namespace {

using test::renderPfm;
using test::runCliOrFail;
using test::scratchDirectory;

std::vector<unsigned char> readPng(const std::filesystem::path& path)
{
    int width = 0;
    int height = 0;
    int channels = 0;
    stbi_uc* pixels = stbi_load(path.string().c_str(), &width, &height, &channels, 3);
    EXPECT_NE(pixels, nullptr) << path;
    if (!pixels)
        return {};
    std::vector<unsigned char> bytes(pixels, pixels + static_cast<std::size_t>(width) * height * 3);
    stbi_image_free(pixels);
    return bytes;
}

// A lit scene with values well above 1 (so that the tone curves matter), small enough to run
// every technique quickly.
const std::string kScene = MANYLIGHTS_SOURCE_DIR "/tests/scenes/spots_and_points.json";
const std::vector<std::string> kSmall{"--size", "96x64"};

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more)
{
    args.insert(args.end(), more.begin(), more.end());
    return args;
}

TEST(DisplayOutput, DefaultPngIsThePlainClampOfTheLinearColour)
{
    const auto dir = scratchDirectory();
    const Image linear = renderPfm(kScene, dir / "linear.pfm", kSmall);
    runCliOrFail(with({"render", kScene, "-o", (dir / "plain.png").string()}, kSmall));
    const std::vector<unsigned char> png = readPng(dir / "plain.png");
    ASSERT_EQ(png.size(), linear.rgb.size());
    int above = 0;
    for (std::size_t i = 0; i < png.size(); ++i) {
        ASSERT_EQ(png[i], toByte(linear.rgb[i])) << "value " << i;
        above += linear.rgb[i] > 1.0f;
    }
    EXPECT_GT(above, 0) << "the scene must have values the tone curves compress";
}

TEST(DisplayOutput, AcesPngIsTheFormulaOfThePfm)
{
    const auto dir = scratchDirectory();
    runCliOrFail(with({"render", kScene, "-o", (dir / "plain.png").string()}, kSmall));
    runCliOrFail(
        with({"render", kScene, "-o", (dir / "aces.png").string(), "--tonemap", "aces", "--srgb", "--exposure", "-1"},
             kSmall));
    const std::vector<unsigned char> plain = readPng(dir / "plain.png");
    const std::vector<unsigned char> aces = readPng(dir / "aces.png");
    const Image linear = renderPfm(kScene, dir / "linear.pfm", kSmall);
    // Pixel by pixel, the ACES PNG is the formula of the linear value halved: within half a
    // level of quantisation plus a quarter for the GPU's pow and division (as
    // tests/gl/DisplayPassTest.cpp).
    for (std::size_t i = 0; i < aces.size(); ++i) {
        const double x = 0.5 * linear.rgb[i];
        double mapped = std::clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
        mapped = mapped <= 0.0031308 ? 12.92 * mapped : 1.055 * std::pow(mapped, 1.0 / 2.4) - 0.055;
        ASSERT_NEAR(aces[i], 255.0 * mapped, 0.75) << "value " << i;
    }
    EXPECT_NE(plain, aces);
}

TEST(DisplayOutput, SceneDisplayBlockAndCommandLineOverride)
{
    const auto dir = scratchDirectory();
    std::ifstream in(kScene);
    nlohmann::json scene = nlohmann::json::parse(in);
    scene["display"] = {{"tonemap", "reinhard"}, {"srgb", true}, {"exposure", 1}};
    test::writeFile(dir / "scene.json", scene.dump());
    const std::string path = (dir / "scene.json").string();
    runCliOrFail(with({"render", path, "-o", (dir / "from-scene.png").string()}, kSmall));
    runCliOrFail(with({"render", kScene, "-o", (dir / "from-flags.png").string(), "--tonemap", "reinhard", "--srgb",
                       "--exposure", "1"},
                      kSmall));
    EXPECT_EQ(readPng(dir / "from-scene.png"), readPng(dir / "from-flags.png"));
    // The command line wins over the scene: back to the plain look.
    runCliOrFail(with(
        {"render", path, "-o", (dir / "overridden.png").string(), "--tonemap", "none", "--no-srgb", "--exposure", "0"},
        kSmall));
    runCliOrFail(with({"render", kScene, "-o", (dir / "plain.png").string()}, kSmall));
    EXPECT_EQ(readPng(dir / "overridden.png"), readPng(dir / "plain.png"));
}

class DisplayedTechnique : public ::testing::TestWithParam<std::string> {};

TEST_P(DisplayedTechnique, MatchesForwardThroughTheDisplayPath)
{
    // The display pass runs after lighting on the lit image alone, so the techniques' PNGs
    // under a tone curve and sRGB differ from forward's only by their lit images' differences
    // (TechniqueAgreementTest's 1e-5 relative with the seed layout), which 8 bits round away
    // but for a value that falls at a rounding boundary: at most one level.
    const auto dir = scratchDirectory();
    const std::vector<std::string> display{"--tonemap", "agx", "--srgb", "--gbuffer", "seed"};
    runCliOrFail(with(with({"render", kScene, "-o", (dir / "forward.png").string(), "--technique", "forward"}, kSmall),
                      display));
    runCliOrFail(with(
        with({"render", kScene, "-o", (dir / "technique.png").string(), "--technique", GetParam()}, kSmall), display));
    const std::vector<unsigned char> forward = readPng(dir / "forward.png");
    const std::vector<unsigned char> technique = readPng(dir / "technique.png");
    ASSERT_EQ(forward.size(), technique.size());
    for (std::size_t i = 0; i < forward.size(); ++i)
        ASSERT_NEAR(technique[i], forward[i], 1) << "value " << i;
}

INSTANTIATE_TEST_SUITE_P(EveryTechnique, DisplayedTechnique,
                         ::testing::Values("deferred", "volumes", "stencil", "tiled-quads", "tiled", "clustered"),
                         test::techniqueTestName);

TEST(DisplayOutput, SupersampledPfmIsTheBoxFilteredLargerFrame)
{
    const auto dir = scratchDirectory();
    const Image large = renderPfm(kScene, dir / "large.pfm", {"--size", "192x128"});
    const Image supersampled = renderPfm(kScene, dir / "supersampled.pfm", {"--size", "96x64", "--supersample", "2"});
    const Image expected = boxDownsample(large, 2);
    ASSERT_EQ(supersampled.width, 96);
    ASSERT_EQ(supersampled.rgb, expected.rgb);
    // And the PNG of it goes through the GPU's box filter: the same values within rounding.
    runCliOrFail(
        {"render", kScene, "-o", (dir / "supersampled.png").string(), "--size", "96x64", "--supersample", "2"});
    const std::vector<unsigned char> png = readPng(dir / "supersampled.png");
    ASSERT_EQ(png.size(), expected.rgb.size());
    for (std::size_t i = 0; i < png.size(); ++i)
        ASSERT_NEAR(png[i], 255.0 * std::clamp(expected.rgb[i], 0.0f, 1.0f), 0.5 + 1e-3) << "value " << i;
}

TEST(DisplayOutput, ExrFloatHoldsThePfmAndEveryAovEqualsItsView)
{
    const auto dir = scratchDirectory();
    const std::string scene = MANYLIGHTS_SOURCE_DIR "/tests/scenes/shadows_and_ssao.json";
    runCliOrFail(with({"render", scene, "-o", (dir / "frame.exr").string(), "--exr-float", "--aovs"}, kSmall));
    const Image colour = readExrLayer(dir / "frame.exr", "", {"R", "G", "B"});
    EXPECT_EQ(colour.rgb, renderPfm(scene, dir / "final.pfm", kSmall).rgb);
    const std::vector<std::pair<std::string, std::vector<std::string>>> aovs{{"position", {"X", "Y", "Z"}},
                                                                             {"normal", {"X", "Y", "Z"}},
                                                                             {"diffuse", {"R", "G", "B"}},
                                                                             {"specular", {"R", "G", "B"}},
                                                                             {"emissive", {"R", "G", "B"}},
                                                                             {"depth", {"Z"}},
                                                                             {"light-count", {"Y"}},
                                                                             {"shadow", {"Y"}},
                                                                             {"ssao", {"Y"}}};
    const std::vector<std::string> names = exrChannelNames(dir / "frame.exr");
    EXPECT_EQ(names.size(), 3u + 3 * 5 + 4);
    for (const auto& [view, channels] : aovs) {
        const Image layer = readExrLayer(dir / "frame.exr", view, channels);
        const Image expected = renderPfm(scene, dir / (view + ".pfm"), with(kSmall, {"--view", view}));
        for (std::size_t i = 0; i < expected.rgb.size(); ++i) {
            if (i % 3 >= channels.size())
                continue;  // a one-channel layer holds the view's first channel
            ASSERT_EQ(layer.rgb[i], expected.rgb[i]) << view << ", value " << i;
        }
    }
}

TEST(DisplayOutput, ExrHalfIsThePfmWithinHalfPrecision)
{
    const auto dir = scratchDirectory();
    runCliOrFail(with({"render", kScene, "-o", (dir / "frame.exr").string()}, kSmall));
    const Image half = readExrLayer(dir / "frame.exr", "", {"R", "G", "B"});
    const Image pfm = renderPfm(kScene, dir / "final.pfm", kSmall);
    ASSERT_EQ(half.rgb.size(), pfm.rgb.size());
    for (std::size_t i = 0; i < pfm.rgb.size(); ++i) {
        // Half keeps 11 significant bits: rounding to nearest errs by at most 2^-11 relative;
        // below 2^-14 (subnormal halves) by at most 2^-25 absolute.
        ASSERT_NEAR(half.rgb[i], pfm.rgb[i], std::abs(pfm.rgb[i]) * 0x1p-11f + 0x1p-25f) << "value " << i;
    }
}

TEST(DisplayOutput, ExrOpensInExrheader)
{
    if (std::system("command -v exrheader > /dev/null 2>&1") != 0)
        GTEST_SKIP() << "exrheader (Debian package openexr) is not installed";
    const auto dir = scratchDirectory();
    runCliOrFail(with({"render", kScene, "-o", (dir / "frame.exr").string(), "--aovs"}, kSmall));
    const std::string command =
        "exrheader '" + (dir / "frame.exr").string() + "' > '" + (dir / "header.txt").string() + "'";
    ASSERT_EQ(std::system(command.c_str()), 0);
    std::ifstream in(dir / "header.txt");
    const std::string header((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (const char* channel : {"R, 16-bit floating-point", "normal.X", "light-count.Y", "ssao.Y"})
        EXPECT_NE(header.find(channel), std::string::npos) << channel << " missing in:\n" << header;
}

TEST(DisplayOutput, ExrReadingErrorsNameTheFile)
{
    const auto dir = scratchDirectory();
    runCliOrFail(with({"render", kScene, "-o", (dir / "frame.exr").string()}, kSmall));
    // A layer the file does not have: the file and the channel.
    try {
        readExrLayer(dir / "frame.exr", "normal", {"X", "Y", "Z"});
        ADD_FAILURE() << "a missing layer must be an error";
    } catch (const Error& error) {
        EXPECT_NE(std::string(error.what()).find("frame.exr"), std::string::npos) << error.what();
        EXPECT_NE(std::string(error.what()).find("normal.X"), std::string::npos) << error.what();
    }
    // Not an EXR file at all.
    test::writeFile(dir / "not.exr", "P6\n1 1\n255\n\0\0\0");
    EXPECT_THROW(readExrLayer(dir / "not.exr", "", {"R"}), Error);
    EXPECT_THROW(exrChannelNames(dir / "not.exr"), Error);
}

}  // namespace
}  // namespace manylights
