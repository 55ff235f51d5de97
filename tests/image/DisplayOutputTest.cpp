// The display path and the scene-referred outputs through the command line
// (docs/display.md): the default PNG is PBR Neutral then sRGB of the PFM's values, the AgX
// PNG AgX then sRGB of them, and
// `--tonemap none --no-srgb` (`--classic`) the contract's plain clamp; tone mapping, sRGB
// and FXAA change only 8-bit outputs, after lighting, so every technique still matches
// forward there; --supersample box-filters in linear light; EXR files hold the PFM's values
// (bit-exact as float, within half precision as half) and, with --aovs, every G-buffer view
// as a layer equal to that view's PFM. The light-count PNG's legend changes its own area only.
#include <gtest/gtest.h>

#include <stb/stb_image.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "TestSupport.h"
#include "core/Error.h"
#include "render/HeatMapLegend.h"
#include "render/Techniques.h"
#include "render/Views.h"
#include "render/output/ExrFile.h"
#include "render/output/Image.h"
#include "render/techniques/Technique.h"
#include "tests/support/ImageComparison.h"
#include "tests/support/PbrNeutral.h"

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
// The classic look, round(255 · clamp(v, 0, 1)): SPEC.md §3's flags for it.
const std::vector<std::string> kClassic{"--tonemap", "none", "--no-srgb"};

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more)
{
    args.insert(args.end(), more.begin(), more.end());
    return args;
}

TEST(DisplayOutput, ClassicPngIsThePlainClampOfTheLinearColour)
{
    const auto dir = scratchDirectory();
    const Image linear = renderPfm(kScene, dir / "linear.pfm", kSmall);
    runCliOrFail(with(with({"render", kScene, "-o", (dir / "plain.png").string()}, kSmall), kClassic));
    const std::vector<unsigned char> png = readPng(dir / "plain.png");
    ASSERT_EQ(png.size(), linear.rgb.size());
    int above = 0;
    for (std::size_t i = 0; i < png.size(); ++i) {
        ASSERT_EQ(png[i], toByte(linear.rgb[i])) << "value " << i;
        above += linear.rgb[i] > 1.0f;
    }
    EXPECT_GT(above, 0) << "the scene must have values the tone curves compress";
    // --classic is the same two flags.
    runCliOrFail(with({"render", kScene, "-o", (dir / "classic.png").string(), "--classic"}, kSmall));
    EXPECT_EQ(readPng(dir / "classic.png"), png);
}

// Sobotka's AgX as Wrensch's minimal fit (2023), typed from the post (column-major, as GLSL's
// mat3 constructor takes them), then IEC 61966-2-1's sRGB encoding: one pixel's linear RGB to
// its display-encoded RGB.
std::array<double, 3> agxThenSrgb(const float* linear)
{
    const double inset[3][3] = {{0.842479062253094, 0.0423282422610123, 0.0423756549057051},
                                {0.0784335999999992, 0.878468636469772, 0.0784336},
                                {0.0792237451477643, 0.0791661274605434, 0.879142973793104}};
    const double outset[3][3] = {{1.19687900512017, -0.0528968517574562, -0.0529716355144438},
                                 {-0.0980208811401368, 1.15190312990417, -0.0980434501171241},
                                 {-0.0990297440797205, -0.0989611768448433, 1.15107367264116}};
    const double minStops = -12.47393;
    const double maxStops = 4.026069;
    std::array<double, 3> curve{};
    for (int row = 0; row < 3; ++row) {
        double v = 0.0;
        for (int column = 0; column < 3; ++column)
            v += inset[column][row] * std::max(static_cast<double>(linear[column]), 0.0);
        v = (std::clamp(std::log2(std::max(v, 1e-10)), minStops, maxStops) - minStops) / (maxStops - minStops);
        const double v2 = v * v;
        const double v4 = v2 * v2;
        curve[row] = 15.5 * v4 * v2 - 40.14 * v4 * v + 31.96 * v4 - 6.868 * v2 * v + 0.4298 * v2 + 0.1191 * v - 0.00232;
    }
    std::array<double, 3> encoded{};
    for (int row = 0; row < 3; ++row) {
        double v = 0.0;
        for (int column = 0; column < 3; ++column)
            v += outset[column][row] * curve[column];
        const double display = std::pow(std::clamp(v, 0.0, 1.0), 2.2);  // the 2.2-power display's light
        encoded[row] = display <= 0.0031308 ? 12.92 * display : 1.055 * std::pow(display, 1.0 / 2.4) - 0.055;
    }
    return encoded;
}

double srgbEncoded(double display)
{
    display = std::clamp(display, 0.0, 1.0);
    return display <= 0.0031308 ? 12.92 * display : 1.055 * std::pow(display, 1.0 / 2.4) - 0.055;
}

// Khronos PBR Neutral (tests/support/PbrNeutral.h), then IEC 61966-2-1's sRGB encoding.
std::array<double, 3> pbrNeutralThenSrgb(const float* linear)
{
    std::array<double, 3> encoded = test::pbrNeutral(
        {std::max<double>(linear[0], 0.0), std::max<double>(linear[1], 0.0), std::max<double>(linear[2], 0.0)});
    for (double& c : encoded)
        c = srgbEncoded(c);
    return encoded;
}

TEST(DisplayOutput, DefaultPngIsPbrNeutralAndAgxPngAgxThenSrgbOfThePfm)
{
    // Pixel by pixel, the default PNG is the PFM's colour through PBR Neutral (the default
    // curve since issue 48) and the sRGB encoding, and the --tonemap agx PNG the same through
    // AgX: within half a level of quantisation plus a quarter for the GPU's arithmetic (as
    // tests/gl/DisplayPassTest.cpp, whose inputs pin each curve down).
    const auto dir = scratchDirectory();
    const Image linear = renderPfm(kScene, dir / "linear.pfm", kSmall);
    runCliOrFail(with({"render", kScene, "-o", (dir / "default.png").string()}, kSmall));
    runCliOrFail(with({"render", kScene, "-o", (dir / "agx.png").string(), "--tonemap", "agx"}, kSmall));
    const std::vector<unsigned char> png = readPng(dir / "default.png");
    const std::vector<unsigned char> agx = readPng(dir / "agx.png");
    ASSERT_EQ(png.size(), linear.rgb.size());
    ASSERT_EQ(agx.size(), linear.rgb.size());
    for (std::size_t i = 0; i < png.size(); i += 3) {
        const std::array<double, 3> expected = pbrNeutralThenSrgb(&linear.rgb[i]);
        const std::array<double, 3> expectedAgx = agxThenSrgb(&linear.rgb[i]);
        for (std::size_t c = 0; c < 3; ++c) {
            ASSERT_NEAR(png[i + c], 255.0 * expected[c], 0.75) << "value " << i + c;
            ASSERT_NEAR(agx[i + c], 255.0 * expectedAgx[c], 0.75) << "value " << i + c << " (agx)";
        }
    }
    // Analytic pixels. Middle grey, 0.18, under PBR Neutral: 0.18 − 0.04 = 0.14, below the
    // shoulder, which sRGB encodes as 1.055 · 0.14^(1/2.4) − 0.055 = 0.41003: 104.56 of 255.
    // Under AgX (AgX's pivot): log2(0.18 · 0.9999) = -2.4737 stops, 0.6061 of the way up AgX's
    // 16.5; the polynomial gives 0.4968, the outset matrix 0.4967, the 2.2 power 0.2145 as
    // display light, and sRGB encodes that as 0.5005: 127.62 of 255. The formulas above must
    // agree to 0.01 level.
    const float grey[3] = {0.18f, 0.18f, 0.18f};
    EXPECT_NEAR(255.0 * pbrNeutralThenSrgb(grey)[0], 104.56, 0.01);
    EXPECT_NEAR(255.0 * agxThenSrgb(grey)[0], 127.62, 0.01);
    // And not the classic look.
    runCliOrFail(with(with({"render", kScene, "-o", (dir / "classic.png").string()}, kSmall), kClassic));
    EXPECT_NE(readPng(dir / "classic.png"), png);
}

TEST(DisplayOutput, AcesPngIsTheFormulaOfThePfm)
{
    const auto dir = scratchDirectory();
    runCliOrFail(with(with({"render", kScene, "-o", (dir / "plain.png").string()}, kSmall), kClassic));
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
    runCliOrFail(with(with({"render", kScene, "-o", (dir / "plain.png").string()}, kSmall), kClassic));
    EXPECT_EQ(readPng(dir / "overridden.png"), readPng(dir / "plain.png"));
    // A block that sets the exposure alone keeps the default curve and encoding.
    scene["display"] = {{"exposure", 1}};
    test::writeFile(dir / "exposure.json", scene.dump());
    runCliOrFail(with({"render", (dir / "exposure.json").string(), "-o", (dir / "exposure.png").string()}, kSmall));
    runCliOrFail(with({"render", kScene, "-o", (dir / "default-at-1.png").string(), "--exposure", "1"}, kSmall));
    EXPECT_EQ(readPng(dir / "exposure.png"), readPng(dir / "default-at-1.png"));
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
        with({"render", kScene, "-o", (dir / "supersampled.png").string(), "--size", "96x64", "--supersample", "2"},
             kClassic));
    const std::vector<unsigned char> png = readPng(dir / "supersampled.png");
    ASSERT_EQ(png.size(), expected.rgb.size());
    for (std::size_t i = 0; i < png.size(); ++i)
        ASSERT_NEAR(png[i], 255.0 * std::clamp(expected.rgb[i], 0.0f, 1.0f), test::kEightBitConversionTolerance)
            << "value " << i;
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
    const std::string header = test::readFile(dir / "header.txt");
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

// The light-count view's PNG carries a labelled colour bar (render/HeatMapLegend.h) in its
// legend area only; --no-legend gives the plain heat map of the counts, pixel for pixel.
TEST(DisplayOutput, LightCountLegendChangesOnlyItsAreaAndNoLegendIsThePlainHeatMap)
{
    const auto dir = scratchDirectory();
    const int width = 320;
    const int height = 180;
    const std::vector<std::string> args{"--size", "320x180", "--view", "light-count", "--technique", "deferred"};
    runCliOrFail(with({"render", "-o", (dir / "legend.png").string()}, args));
    runCliOrFail(with({"render", "-o", (dir / "plain.png").string(), "--no-legend"}, args));
    const Image counts = renderPfm("", dir / "counts.pfm", args);
    const std::vector<unsigned char> legend = readPng(dir / "legend.png");
    const std::vector<unsigned char> plain = readPng(dir / "plain.png");
    ASSERT_EQ(legend.size(), std::size_t(width * height * 3));
    ASSERT_EQ(plain.size(), legend.size());

    const LegendArea area = heatMapLegendArea(width, height);
    ASSERT_FALSE(area.isEmpty());
    int changedInside = 0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 3;
            float rgb[3];
            heatMapColour(counts.pixel(x, y)[0], rgb);
            for (int c = 0; c < 3; ++c)
                ASSERT_EQ(plain[i + c], toByte(rgb[c])) << x << ", " << y;
            const bool inside = x >= area.x && x < area.x + area.width && y >= area.y && y < area.y + area.height;
            const bool same = std::equal(&legend[i], &legend[i] + 3, &plain[i]);
            if (!inside)
                ASSERT_TRUE(same) << "outside the legend: " << x << ", " << y;
            else
                changedInside += same ? 0 : 1;
        }
    }
    // The panel, the bar and the labels cover most of the area.
    EXPECT_GT(changedInside, area.width * area.height / 2);
}

// The title as the legend's font drew it at `place` in an RGB image of `width` pixels a row:
// each character cell read back as 3 x 5 on/off pixels (white is on) and matched against the
// font; '?' for a cell that matches no character.
std::string readLegendTitle(const std::vector<unsigned char>& rgb, int width, const LegendTitlePlace& place,
                            int characters)
{
    std::string title;
    for (int i = 0; i < characters; ++i) {
        std::array<unsigned char, kLegendGlyphHeight> rows{};
        for (int row = 0; row < kLegendGlyphHeight; ++row)
            for (int column = 0; column < kLegendGlyphWidth; ++column) {
                const int x = place.x + (i * kLegendGlyphAdvance + column) * place.scale;
                const int y = place.y + row * place.scale;
                const unsigned char* pixel = &rgb[(static_cast<std::size_t>(y) * width + x) * 3];
                if (pixel[0] > 200 && pixel[1] > 200 && pixel[2] > 200)
                    rows[static_cast<std::size_t>(row)] |=
                        static_cast<unsigned char>(1 << (kLegendGlyphWidth - 1 - column));
            }
        char read = '?';
        for (char c : std::string(legendCharacters()) + " ")
            if (legendGlyph(c) == rows)
                read = c;
        title += read;
    }
    return title;
}

// The legend's title names what is counted (issue 43), read back from render's PNG pixel by
// pixel: light evaluations per pixel, and which lights the technique evaluates there.
TEST(DisplayOutput, LightCountLegendTitleNamesWhatIsCounted)
{
    // Every character the titles use has a glyph of its own, so that the reading is exact.
    for (char a : legendCharacters()) {
        EXPECT_NE(legendGlyph(a), legendGlyph(' ')) << a;
        for (char b : legendCharacters()) {
            if (a != b) {
                EXPECT_NE(legendGlyph(a), legendGlyph(b)) << a << " and " << b;
            }
        }
    }
    const auto dir = scratchDirectory();
    const int width = 320;
    const int height = 180;
    for (const std::string technique : {"deferred", "tiled", "clustered"}) {
        const std::string title = heatMapLegendTitle(technique);
        for (char c : title)
            EXPECT_TRUE(c == ' ' || legendCharacters().find(c) != std::string_view::npos) << title;
        const auto path = dir / (technique + ".png");
        runCliOrFail(
            {"render", "-o", path.string(), "--size", "320x180", "--view", "light-count", "--technique", technique});
        const std::vector<unsigned char> png = readPng(path);
        ASSERT_EQ(png.size(), std::size_t(width * height * 3));
        EXPECT_EQ(readLegendTitle(png, width, heatMapLegendTitlePlace(width, height), static_cast<int>(title.size())),
                  title);
    }
    EXPECT_EQ(heatMapLegendTitle("deferred"), "LIGHT EVALUATIONS PER PIXEL: EVERY LIGHT");
    EXPECT_EQ(heatMapLegendTitle("tiled"), "LIGHT EVALUATIONS PER PIXEL: TILE'S LIGHTS IN REACH");
    EXPECT_EQ(heatMapLegendTitle("clustered"), "LIGHT EVALUATIONS PER PIXEL: CLUSTER'S LIGHTS IN REACH");
    // Every technique's title fits the legend (drawHeatMapLegend asserts it).
    for (const std::string& technique : techniqueNames()) {
        Image image;
        image.width = width;
        image.height = height;
        image.rgb.assign(static_cast<std::size_t>(width) * height * 3, 0.0f);
        drawHeatMapLegend(image, 1.0f, heatMapLegendTitle(technique));
    }
}

// --view shadow-resolution where no local light casts a shadow (no --shadow-lights, and the
// default scene asks for none): no pixel has a figure, so the image is black, and it still
// carries its legend, which says NONE where the figures' range would be (docs/shadows.md). The
// view is drawn whatever technique is named.
TEST(DisplayOutput, ShadowResolutionWithoutShadowedLightsIsBlackWithItsLegend)
{
    const auto dir = scratchDirectory();
    const int width = 320;
    const int height = 180;
    const std::vector<std::string> args{"--size", "320x180", "--view", "shadow-resolution", "--technique", "stencil"};
    runCliOrFail(with({"render", "-o", (dir / "view.png").string()}, args));
    const Image figures = renderPfm("", dir / "view.pfm", args);
    for (const float value : figures.rgb)
        ASSERT_EQ(value, 0.0f);
    const std::vector<unsigned char> png = readPng(dir / "view.png");
    ASSERT_EQ(png.size(), std::size_t(width * height * 3));
    const LegendArea area = heatMapLegendArea(width, height);
    ASSERT_FALSE(area.isEmpty());
    int legendPixels = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 3;
            const bool inside = x >= area.x && x < area.x + area.width && y >= area.y && y < area.y + area.height;
            const bool black = png[i] == 0 && png[i + 1] == 0 && png[i + 2] == 0;
            if (!inside)
                ASSERT_TRUE(black) << x << ", " << y;
            else
                legendPixels += black ? 0 : 1;
        }
    EXPECT_EQ(legendPixels, area.width * area.height);  // the panel is grey, nothing in it black
    const std::string title(kShadowResolutionLegendTitle);
    EXPECT_EQ(readLegendTitle(png, width, heatMapLegendTitlePlace(width, height), static_cast<int>(title.size())),
              title);
}

// Too small an image keeps the plain heat map: the legend would hide most of it.
TEST(DisplayOutput, LightCountLegendNeedsRoom)
{
    EXPECT_TRUE(heatMapLegendArea(96, 54).isEmpty());
    EXPECT_FALSE(heatMapLegendArea(320, 180).isEmpty());
    const LegendArea hd = heatMapLegendArea(1920, 1080);
    EXPECT_EQ(hd.width, 3 * heatMapLegendArea(320, 180).width);  // three times the scale at 1080 rows
    EXPECT_EQ(hd.y + hd.height + hd.x, 1080);                    // the bottom-left corner, one margin in
}

}  // namespace
}  // namespace manylights
