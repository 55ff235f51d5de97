// Golden images: whole renders compared with stored PNGs, to catch any change to what the
// default scene and the test scenes look like (generation of lights and objects, shading,
// views). Regenerate after an intended change with scripts/update-goldens.sh, and look at
// the new images before committing them.
//
// Tolerance: at most 0.2% of pixels may differ by more than 2 levels in any channel. The
// goldens come from Mesa's llvmpipe; another driver or LLVM version rounds floats
// differently (≤ 1–2 levels) and may break rasterisation ties at silhouettes differently
// (whole pixels, but few). A real regression changes far more than 0.2% of the image.
#include <gtest/gtest.h>

#include <cstdlib>

#include <stb/stb_image.h>

#include "TestSupport.h"

namespace manylights {
namespace {

using test::runCliOrFail;
using test::scratchDirectory;

struct Png {
    int width = 0;
    int height = 0;
    std::vector<unsigned char> rgb;
};

Png readPng(const std::filesystem::path& path)
{
    Png png;
    int channels = 0;
    unsigned char* data = stbi_load(path.c_str(), &png.width, &png.height, &channels, 3);
    if (data) {
        png.rgb.assign(data, data + static_cast<std::size_t>(png.width) * png.height * 3);
        stbi_image_free(data);
    }
    return png;
}

struct GoldenCase {
    std::string name;  // tests/golden/<name>.png
    std::vector<std::string> args;
    // Names the case in test listings instead of dumping its bytes.
    friend void PrintTo(const GoldenCase& c, std::ostream* os) { *os << c.name; }
};

class Golden : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(Golden, MatchesStoredImage)
{
    const GoldenCase& c = GetParam();
    const auto dir = scratchDirectory();
    const std::filesystem::path actualPath = dir / "actual.png";
    std::vector<std::string> args = {"render", "-o", actualPath.string()};
    args.insert(args.end(), c.args.begin(), c.args.end());
    runCliOrFail(args);
    const std::filesystem::path goldenPath =
        std::filesystem::path(MANYLIGHTS_SOURCE_DIR) / "tests/golden" / (c.name + ".png");
    if (std::getenv("MANYLIGHTS_UPDATE_GOLDENS")) {
        std::filesystem::copy_file(actualPath, goldenPath, std::filesystem::copy_options::overwrite_existing);
        GTEST_SKIP() << "updated " << goldenPath;
    }
    const Png golden = readPng(goldenPath);
    const Png actual = readPng(actualPath);
    ASSERT_GT(golden.width, 0) << "missing golden " << goldenPath << ": run scripts/update-goldens.sh";
    ASSERT_EQ(actual.width, golden.width);
    ASSERT_EQ(actual.height, golden.height);

    Image difference;
    difference.width = golden.width;
    difference.height = golden.height;
    difference.rgb.assign(golden.rgb.size(), 0.0f);
    int differing = 0;
    int lit = 0;
    const std::size_t pixels = static_cast<std::size_t>(golden.width) * golden.height;
    for (std::size_t i = 0; i < pixels; ++i) {
        int worst = 0;
        for (int channel = 0; channel < 3; ++channel) {
            const int delta = std::abs(int(golden.rgb[i * 3 + channel]) - int(actual.rgb[i * 3 + channel]));
            worst = std::max(worst, delta);
            difference.rgb[i * 3 + channel] = static_cast<float>(delta) / 16.0f;  // amplified for the eye
            lit += golden.rgb[i * 3 + channel] > 0;
        }
        differing += worst > 2;
    }
    EXPECT_GT(lit, 0) << "the golden image is black: it proves nothing";
    const double fraction = static_cast<double>(differing) / static_cast<double>(pixels);
    EXPECT_LE(fraction, 0.002) << differing << " pixels differ by more than 2 levels; see " << dir;
    if (HasFailure())
        writePng(difference, dir / "difference.png");
}

INSTANTIATE_TEST_SUITE_P(
    Images, Golden,
    // The final views in the classic look (--tonemap none --no-srgb), which these goldens have
    // held since before the default became display-encoded; default_agx_deferred_320x180 is
    // AgX and sRGB (the default look from 2026-11-25 until issue 48, now named), and
    // default_look_deferred_320x180 the default look itself (PBR Neutral and sRGB).
    ::testing::Values(GoldenCase{"default_deferred_320x180",
                                 {"--size", "320x180", "--technique", "deferred", "--tonemap", "none", "--no-srgb"}},
                      GoldenCase{"default_agx_deferred_320x180",
                                 {"--size", "320x180", "--technique", "deferred", "--tonemap", "agx"}},
                      GoldenCase{"default_look_deferred_320x180", {"--size", "320x180", "--technique", "deferred"}},
                      GoldenCase{"default_normal_320x180", {"--size", "320x180", "--view", "normal"}},
                      GoldenCase{"spots_and_points_forward_240x160",
                                 {MANYLIGHTS_SOURCE_DIR "/tests/scenes/spots_and_points.json", "--size", "240x160",
                                  "--technique", "forward", "--tonemap", "none", "--no-srgb"}}),
    [](const ::testing::TestParamInfo<GoldenCase>& param) { return param.param.name; });

}  // namespace
}  // namespace manylights
