// The executable as users and scripts meet it: exit status (0, 1 bad input, 2 bad command
// line), exactly one line on stderr naming the file and position, and never a file written
// under the requested name when it fails. Run as a child process, so a crash shows as one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string_view>

#include <nlohmann/json.hpp>

#include "TestSupport.h"
#include "apps/cli/OutputOptions.h"

namespace manylights {
namespace {

using test::runExecutable;
using test::scratchDirectory;
using test::writeFile;

struct FailureCase {
    std::string name;
    std::string sceneText;          // written to scene.json; empty: no scene argument
    std::vector<std::string> args;  // after "render [scene.json] -o out.png"
    int exitCode;
    std::vector<std::string> messageParts;  // each must appear in the one stderr line
    // Names the case in test listings instead of dumping its bytes.
    friend void PrintTo(const FailureCase& c, std::ostream* os) { *os << c.name; }
};

class CliFailure : public ::testing::TestWithParam<FailureCase> {};

TEST_P(CliFailure, OneLineAndNothingWritten)
{
    const FailureCase& c = GetParam();
    const auto dir = scratchDirectory();
    std::vector<std::string> args = {"render"};
    if (!c.sceneText.empty()) {
        writeFile(dir / "scene.json", c.sceneText);
        args.push_back((dir / "scene.json").string());
    }
    args.insert(args.end(), {"-o", (dir / "out.png").string()});
    args.insert(args.end(), c.args.begin(), c.args.end());
    const test::ProcessResult result = runExecutable(args);
    EXPECT_EQ(result.exitCode, c.exitCode) << result.stderrText;
    if (c.exitCode == 1) {
        EXPECT_EQ(test::lineCount(result.stderrText), 1) << result.stderrText;
    }
    for (const std::string& part : c.messageParts)
        EXPECT_NE(result.stderrText.find(part), std::string::npos)
            << "missing '" << part << "' in: " << result.stderrText;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
    // No temporary left behind either.
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        EXPECT_EQ(entry.path().filename().string().find("out.png"), std::string::npos) << entry.path();
}

const char* kPlane = R"("objects": [{"mesh": {"primitive": "plane", "size": [2, 2]}}])";

// A size the command line accepts (up to kMaxImageDimension, 32,768, a side) but the driver
// does not is bad input: one line naming the size and the driver's limit, exit 1, nothing
// written. The limit is the driver's own (GL_MAX_TEXTURE_SIZE and GL_MAX_FRAMEBUFFER_WIDTH:
// 16,384 on llvmpipe, 32,768 on an NVIDIA H100), so the test asks the driver it runs on for it,
// through the message, and checks both sides of it; a driver that takes the command line's
// largest size leaves no size to refuse.
TEST(CliFailure, SizeBeyondTheDriversLimitIsOneLineAndNothingWritten)
{
    const auto dir = scratchDirectory();
    writeFile(dir / "scene.json", std::string("{") + kPlane + "}");
    const auto render = [&](const std::string& size) {
        return runExecutable(
            {"render", (dir / "scene.json").string(), "-o", (dir / "out.png").string(), "--size", size});
    };
    const test::ProcessResult widest = render("32768x16");
    if (widest.exitCode == 0)
        GTEST_SKIP() << "this driver renders every width the command line accepts (32,768)";
    int maxWidth = 0;
    int maxHeight = 0;
    const std::size_t limit = widest.stderrText.find("supports (1x1 to ");
    ASSERT_NE(limit, std::string::npos) << widest.stderrText;
    ASSERT_EQ(std::sscanf(widest.stderrText.c_str() + limit, "supports (1x1 to %dx%d)", &maxWidth, &maxHeight), 2)
        << widest.stderrText;
    // GL 4.5 requires GL_MAX_TEXTURE_SIZE and GL_MAX_FRAMEBUFFER_WIDTH of at least 16,384.
    ASSERT_GE(maxWidth, 16384);

    const std::string beyond = std::to_string(maxWidth + 1) + "x16";
    const test::ProcessResult result = render(beyond);
    EXPECT_EQ(result.exitCode, 1) << result.stderrText;
    EXPECT_EQ(test::lineCount(result.stderrText), 1) << result.stderrText;
    EXPECT_NE(result.stderrText.find(beyond), std::string::npos) << result.stderrText;
    EXPECT_NE(result.stderrText.find("supports"), std::string::npos) << result.stderrText;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        EXPECT_EQ(entry.path().filename().string().find("out.png"), std::string::npos) << entry.path();

    // The limit itself renders.
    const test::ProcessResult atLimit = render(std::to_string(maxWidth) + "x16");
    EXPECT_EQ(atLimit.exitCode, 0) << atLimit.stderrText;
    EXPECT_TRUE(std::filesystem::exists(dir / "out.png"));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, CliFailure,
    ::testing::Values(
        FailureCase{"syntax_error",
                    "{\n  \"ambient\": [0, 0, 0],\n  \"background\": [0, 0 0]\n}",
                    {},
                    1,
                    {"scene.json:3:", "syntax error"}},
        FailureCase{"truncated_file", "{\"ambient\": [0, 0", {}, 1, {"scene.json:1:"}},
        FailureCase{"unknown_key",
                    std::string("{\"ambiant\": [0, 0, 0], ") + kPlane + "}",
                    {},
                    1,
                    {"scene.json", "ambiant", "did you mean 'ambient'"}},
        FailureCase{
            "wrong_type", std::string("{\"ambient\": \"dark\", ") + kPlane + "}", {}, 1, {"scene.json", "/ambient"}},
        FailureCase{"negative_range",
                    std::string("{\"lights\": [{\"type\": \"point\", \"pos\": [0, 1, 0], \"intensity\": [1, 1, 1], "
                                "\"range\": -2}], ") +
                        kPlane + "}",
                    {},
                    1,
                    {"scene.json", "/lights/0/range"}},
        FailureCase{"cutoff_out_of_range",
                    std::string("{\"lights\": [{\"type\": \"spot\", \"pos\": [0, 1, 0], \"direction\": [0, -1, 0], "
                                "\"cutoff\": 190, \"intensity\": [1, 1, 1], \"range\": 2}], ") +
                        kPlane + "}",
                    {},
                    1,
                    {"scene.json", "/lights/0/cutoff"}},
        FailureCase{
            "missing_mesh", "{\"objects\": [{\"mesh\": \"models/none.obj\"}]}", {}, 1, {"none.obj", "/objects/0/mesh"}},
        FailureCase{"lights_without_sets",
                    std::string("{") + kPlane + "}",
                    {"--lights", "100"},
                    1,
                    {"scene.json", "light_sets"}},
        FailureCase{"unknown_technique", "", {"--technique", "raytraced"}, 2, {"raytraced"}},
        FailureCase{"unknown_view", "", {"--view", "albedo"}, 2, {"albedo"}},
        FailureCase{"malformed_size", "", {"--size", "1280by720"}, 2, {"--size"}},
        FailureCase{"absurd_size", "", {"--size", "100000x100000"}, 2, {"--size"}},
        FailureCase{"zero_frames", "", {"--frames", "0"}, 2, {"--frames"}},
        FailureCase{"negative_lights", "", {"--lights", "-5"}, 2, {"--lights"}},
        FailureCase{"negative_shadow_lights", "", {"--shadow-lights", "-1"}, 2, {"--shadow-lights"}},
        FailureCase{"shadow_lights_not_a_number", "", {"--shadow-lights", "x"}, 2, {"--shadow-lights", "all"}},
        FailureCase{"shadow_lights_fraction", "", {"--shadow-lights", "1.5"}, 2, {"--shadow-lights", "1.5"}},
        FailureCase{"shadow_lights_signed", "", {"--shadow-lights", "+3"}, 2, {"--shadow-lights", "+3"}},
        FailureCase{"shadow_lights_beyond_an_int", "", {"--shadow-lights", "2147483648"}, 2, {"--shadow-lights"}},
        FailureCase{"shadow_pool_zero", "", {"--shadow-pool-mib", "0"}, 2, {"--shadow-pool-mib", "from 4 to 1024"}},
        FailureCase{
            "shadow_pool_off_the_grain", "", {"--shadow-pool-mib", "3"}, 2, {"--shadow-pool-mib", "multiple of 4"}},
        FailureCase{"shadow_pool_too_large", "", {"--shadow-pool-mib", "2048"}, 2, {"--shadow-pool-mib", "2048"}},
        FailureCase{"shadow_pool_negative", "", {"--shadow-pool-mib", "-4"}, 2, {"--shadow-pool-mib"}},
        FailureCase{"shadow_pool_not_a_number", "", {"--shadow-pool-mib", "x"}, 2, {"--shadow-pool-mib", "'x'"}},
        FailureCase{"shadow_pool_nan", "", {"--shadow-pool-mib", "nan"}, 2, {"--shadow-pool-mib", "'nan'"}},
        FailureCase{"scene_shadow_lights_negative",
                    std::string("{\"shadow_lights\": -1, ") + kPlane + "}",
                    {},
                    1,
                    {"scene.json", "/shadow_lights"}},
        FailureCase{"scene_shadow_lights_other_word",
                    std::string("{\"shadow_lights\": \"most\", ") + kPlane + "}",
                    {},
                    1,
                    {"scene.json", "/shadow_lights", "'all'"}},
        FailureCase{"scene_casts_shadows_not_a_boolean",
                    std::string("{\"lights\": [{\"type\": \"point\", \"pos\": [0, 1, 0], \"intensity\": [1, 1, 1], "
                                "\"range\": 2, \"casts_shadows\": 0}], ") +
                        kPlane + "}",
                    {},
                    1,
                    {"scene.json", "/lights/0/casts_shadows"}},
        FailureCase{"anisotropy_not_a_level", "", {"--anisotropy", "3"}, 2, {"--anisotropy", "auto"}},
        FailureCase{"anisotropy_not_a_number", "", {"--anisotropy", "nan"}, 2, {"--anisotropy"}},
        FailureCase{"ssao_radius_zero",
                    std::string("{\"ssao\": {\"radius\": 0}, ") + kPlane + "}",
                    {},
                    1,
                    {"scene.json", "/ssao/radius"}},
        FailureCase{"exposure_nan", "", {"--exposure", "nan"}, 2, {"--exposure"}},
        FailureCase{"exposure_beyond_range", "", {"--exposure", "40"}, 2, {"--exposure"}},
        FailureCase{"unknown_tone_curve", "", {"--tonemap", "filmic"}, 2, {"--tonemap", "filmic"}},
        FailureCase{"unknown_antialiasing", "", {"--aa", "msaa"}, 2, {"--aa", "msaa"}},
        FailureCase{"srgb_and_no_srgb", "", {"--srgb", "--no-srgb"}, 2, {"--srgb", "--no-srgb"}},
        FailureCase{"classic_and_tonemap", "", {"--classic", "--tonemap", "agx"}, 2, {"--classic", "--tonemap"}},
        FailureCase{"classic_and_srgb", "", {"--classic", "--srgb"}, 2, {"--classic", "--srgb"}},
        FailureCase{"supersample_beyond_range", "", {"--supersample", "9"}, 2, {"--supersample"}},
        FailureCase{"supersample_of_a_gbuffer_view",
                    "",
                    {"--supersample", "2", "--view", "normal"},
                    2,
                    {"--supersample", "normal"}},
        FailureCase{"aovs_into_png", "", {"--aovs"}, 2, {"--aovs", ".exr"}},
        FailureCase{"scene_tone_curve_misspelt",
                    std::string("{\"display\": {\"tonemap\": \"acs\"}, ") + kPlane + "}",
                    {},
                    1,
                    {"scene.json", "/display/tonemap", "did you mean 'aces'"}},
        FailureCase{"scene_exposure_beyond_range",
                    std::string("{\"display\": {\"exposure\": 64}, ") + kPlane + "}",
                    {},
                    1,
                    {"scene.json", "/display/exposure"}},
        FailureCase{"scene_srgb_not_a_boolean",
                    std::string("{\"display\": {\"srgb\": \"yes\"}, ") + kPlane + "}",
                    {},
                    1,
                    {"scene.json", "/display/srgb"}},
        FailureCase{"scene_display_unknown_key",
                    std::string("{\"display\": {\"gamma\": 2.2}, ") + kPlane + "}",
                    {},
                    1,
                    {"scene.json", "gamma"}}),
    [](const ::testing::TestParamInfo<FailureCase>& param) { return param.param.name; });

// The one table of which option applies to which output (apps/cli/OutputOptions.h), gone
// through whole: each option with each output format is either taken (exit 0, the image
// written) or the usage error naming the option and the outputs it applies to (exit 2, no file).
TEST(Cli, EveryOutputOptionIsTakenOnlyWithTheOutputsItAppliesTo)
{
    // What each option needs beside itself; a row added to the table without one here fails.
    const std::map<std::string_view, std::vector<std::string>> arguments{
        {"--exposure", {"--exposure", "1"}},
        {"--tonemap", {"--tonemap", "aces"}},
        {"--srgb", {"--srgb"}},
        {"--no-srgb", {"--no-srgb"}},
        {"--classic", {"--classic"}},
        {"--aa", {"--aa", "fxaa"}},
        {"--no-legend", {"--no-legend", "--view", "light-count"}},
        {"--exr-float", {"--exr-float"}},
        {"--aovs", {"--aovs"}},
    };
    const auto dir = scratchDirectory();
    for (const OutputOption& option : outputOptions()) {
        ASSERT_TRUE(arguments.count(option.name)) << option.name << " has no arguments in this test";
        for (ImageFormat format : {ImageFormat::Png, ImageFormat::Pfm, ImageFormat::Exr}) {
            const std::string what = std::string(option.name) + " with " + std::string(formatExtension(format));
            const auto output = dir / ("out" + std::string(formatExtension(format)));
            std::vector<std::string> args{"render", "-o", output.string(), "--size", "32x18"};
            const std::vector<std::string>& extra = arguments.at(option.name);
            args.insert(args.end(), extra.begin(), extra.end());
            const test::ProcessResult result = runExecutable(args);
            const bool applies =
                std::find(option.formats.begin(), option.formats.end(), format) != option.formats.end();
            if (applies) {
                EXPECT_EQ(result.exitCode, 0) << what << ": " << result.stderrText;
                EXPECT_TRUE(std::filesystem::exists(output)) << what;
            } else {
                EXPECT_EQ(result.exitCode, 2) << what;
                EXPECT_EQ(test::lineCount(result.stderrText), 1) << what << ": " << result.stderrText;
                EXPECT_EQ(result.stderrText.rfind("manylights: " + std::string(option.name) + " applies to ", 0), 0u)
                    << what << ": " << result.stderrText;
                EXPECT_FALSE(std::filesystem::exists(output)) << what;
            }
            std::filesystem::remove(output);
        }
    }
}

TEST(Cli, MissingSceneFileIsOneLineExitOne)
{
    const auto dir = scratchDirectory();
    const test::ProcessResult result =
        runExecutable({"render", (dir / "absent.json").string(), "-o", (dir / "out.png").string()});
    EXPECT_EQ(result.exitCode, 1) << result.stderrText;
    EXPECT_EQ(test::lineCount(result.stderrText), 1) << result.stderrText;
    EXPECT_NE(result.stderrText.find("absent.json"), std::string::npos) << result.stderrText;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
}

TEST(Cli, BadOutputExtensionIsUsageError)
{
    const auto dir = scratchDirectory();
    const test::ProcessResult result = runExecutable({"render", "-o", (dir / "out.jpg").string()});
    EXPECT_EQ(result.exitCode, 2);
    EXPECT_NE(result.stderrText.find(".png, .pfm or .exr"), std::string::npos) << result.stderrText;
}

TEST(Cli, UnwritableOutputIsExitOneWithNothingLeft)
{
    const auto dir = scratchDirectory();
    const test::ProcessResult result =
        runExecutable({"render", "-o", (dir / "no-such-dir" / "out.png").string(), "--size", "32x18"});
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_EQ(test::lineCount(result.stderrText), 1) << result.stderrText;
    EXPECT_NE(result.stderrText.find("out.png"), std::string::npos) << result.stderrText;
}

TEST(Cli, NoOpenGLContextIsExitOneWithTheReason)
{
    // Mesa cannot load a driver named "nonexistent", so every EGL platform fails to
    // initialise. (Mesa itself warns on stderr too, so only our line is looked for.)
    const auto dir = scratchDirectory();
    const test::ProcessResult result =
        runExecutable({"render", "-o", (dir / "out.png").string(), "--size", "32x18"},
                      "GALLIUM_DRIVER=nonexistent MESA_LOADER_DRIVER_OVERRIDE=nonexistent");
    if (result.exitCode == 0)
        GTEST_SKIP() << "this GL driver ignores Mesa's driver override";
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.stderrText.find("manylights: cannot create an OpenGL 4.5 core context ("), std::string::npos)
        << result.stderrText;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
}

TEST(Cli, MissingOutputOptionIsUsageError)
{
    EXPECT_EQ(runExecutable({"render"}).exitCode, 2);
    EXPECT_EQ(runExecutable({}).exitCode, 2);
    EXPECT_EQ(runExecutable({"paint"}).exitCode, 2);
}

TEST(Cli, DefaultSceneRendersToPngAndStatsDescribeThePasses)
{
    const auto dir = scratchDirectory();
    const test::ProcessResult result =
        runExecutable({"render", "-o", (dir / "out.png").string(), "--size", "160x90", "--technique", "deferred",
                       "--frames", "3", "--stats", (dir / "stats.json").string()});
    ASSERT_EQ(result.exitCode, 0) << result.stderrText;
    EXPECT_TRUE(std::filesystem::exists(dir / "out.png"));

    std::ifstream in(dir / "stats.json");
    const nlohmann::json stats = nlohmann::json::parse(in);
    EXPECT_EQ(stats["technique"], "deferred");
    EXPECT_EQ(stats["width"], 160);
    EXPECT_EQ(stats["height"], 90);
    EXPECT_EQ(stats["frames"], 3);
    EXPECT_GE(stats["lights"].get<int>(), 200);
    const double median = stats["frame_ms"]["median"];
    EXPECT_GT(median, 0.0);
    EXPECT_LE(stats["frame_ms"]["min"].get<double>(), median);
    EXPECT_GE(stats["frame_ms"]["max"].get<double>(), median);
    // A PNG in the default look ends with the display pass (PBR Neutral and sRGB since issue
    // 48), timed as its own.
    ASSERT_EQ(stats["passes"].size(), 3u);
    EXPECT_EQ(stats["passes"][0]["name"], "geometry");
    EXPECT_EQ(stats["passes"][1]["name"], "lighting");
    EXPECT_EQ(stats["passes"][2]["name"], "display");
    EXPECT_EQ(stats["display"]["tonemap"], "pbr-neutral");
    EXPECT_EQ(stats["display"]["srgb"], true);
    // --anisotropy auto: none on a software rasteriser, 8 on a GPU (within the driver's maximum).
    const double anisotropy = stats["anisotropy"];
    if (stats["device"].get<std::string>().find("llvmpipe") != std::string::npos) {
        EXPECT_EQ(anisotropy, 1.0);
    } else {
        EXPECT_GE(anisotropy, 1.0);
    }
}

// Issue 47: the shadowed lights are --shadow-lights, else the scene's "shadow_lights", else 0;
// "all" and counts past the old budget of 256 are taken; the pool's size is --shadow-pool-mib,
// else kDefaultShadowPoolMiB (256). --stats reports both as the renderer was given them. One
// light over a plane at 16x16 keeps each run short.
TEST(Cli, ShadowSettingsReachTheRendererAndTheStats)
{
    const auto dir = scratchDirectory();
    const std::string light =
        R"("lights": [{"type": "point", "pos": [0, 1, 0], "intensity": [1, 1, 1], "range": 3}], )";
    writeFile(dir / "plain.json", "{" + light + kPlane + "}");
    writeFile(dir / "all.json", "{\"shadow_lights\": \"all\", " + light + kPlane + "}");
    writeFile(dir / "three.json", "{\"shadow_lights\": 3, " + light + kPlane + "}");
    const auto stats = [&](const std::string& scene, const std::vector<std::string>& options) {
        std::vector<std::string> args{
            "render",  (dir / scene).string(),       "-o", (dir / "out.png").string(), "--size", "16x16",
            "--stats", (dir / "stats.json").string()};
        args.insert(args.end(), options.begin(), options.end());
        const test::ProcessResult result = runExecutable(args);
        EXPECT_EQ(result.exitCode, 0) << result.stderrText;
        std::ifstream in(dir / "stats.json");
        const nlohmann::json json = nlohmann::json::parse(in);
        std::filesystem::remove(dir / "stats.json");
        return std::pair(json.at("shadow_lights"), json.at("shadow_pool_mib"));
    };
    using ShadowStats = std::pair<nlohmann::json, nlohmann::json>;
    EXPECT_EQ(stats("plain.json", {}), ShadowStats(0, 256));
    EXPECT_EQ(stats("all.json", {}), ShadowStats("all", 256));
    EXPECT_EQ(stats("three.json", {}), ShadowStats(3, 256));
    // The command line overrides the scene, either way.
    EXPECT_EQ(stats("all.json", {"--shadow-lights", "257", "--shadow-pool-mib", "8"}), ShadowStats(257, 8));
    EXPECT_EQ(stats("three.json", {"--shadow-lights", "0"}), ShadowStats(0, 256));
    EXPECT_EQ(stats("plain.json", {"--shadow-lights", "all", "--shadow-pool-mib", "1024"}), ShadowStats("all", 1024));
    EXPECT_EQ(stats("plain.json", {"--shadow-lights", "100000", "--shadow-pool-mib", "4", "--rebuild-shadows"}),
              ShadowStats(100000, 4));
}

TEST(Cli, AnisotropyLevelReachesTheTexturesAndTheStats)
{
    const auto dir = scratchDirectory();
    const test::ProcessResult result = runExecutable({"render", "-o", (dir / "out.png").string(), "--size", "64x36",
                                                      "--anisotropy", "4", "--stats", (dir / "stats.json").string()});
    ASSERT_EQ(result.exitCode, 0) << result.stderrText;
    std::ifstream in(dir / "stats.json");
    const nlohmann::json stats = nlohmann::json::parse(in);
    // Every conformant driver with the extension offers at least 2; llvmpipe offers 16.
    EXPECT_LE(stats["anisotropy"].get<double>(), 4.0);
    if (stats["device"].get<std::string>().find("llvmpipe") != std::string::npos) {
        EXPECT_EQ(stats["anisotropy"].get<double>(), 4.0);
    }
}

}  // namespace
}  // namespace manylights
