// Broken material textures through the real executable: exit status 1, one line on stderr that
// names the texture file, nothing written under the output name. And the --gbuffer option's
// bad values (exit 2). Run as a child process, so a crash shows as one.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <stb/stb_image_write.h>

#include "TestSupport.h"

namespace manylights {
namespace {

using test::runExecutable;
using test::scratchDirectory;
using test::writeFile;

// A 64x64 JPEG with detail in every block, in memory.
std::string patternJpeg()
{
    std::vector<unsigned char> rgb;
    for (int i = 0; i < 64 * 64 * 3; ++i)
        rgb.push_back(static_cast<unsigned char>((i * 37 + (i / 192) * 11) % 256));
    std::string bytes;
    const auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
    };
    EXPECT_NE(stbi_write_jpg_to_func(append, &bytes, 64, 64, 3, rgb.data(), 90), 0);
    return bytes;
}

TEST(TextureCli, BrokenTextureIsOneLineExitOneNamingTheFile)
{
    const std::string brick = test::readFile(MANYLIGHTS_SOURCE_DIR "/tests/scenes/textures/brick.png");
    ASSERT_GT(brick.size(), 100u);
    const std::string jpeg = patternJpeg();
    ASSERT_GT(jpeg.size(), 1000u);
    // A PNG header claiming 17000 x 17000 texels: beyond kMaxTextureSide (and most drivers).
    std::string huge = brick.substr(0, 33);
    const char side[4] = {0x00, 0x00, 0x42, 0x68};
    huge.replace(16, 4, side, 4);
    huge.replace(20, 4, side, 4);
    const std::pair<std::string, std::string> cases[] = {
        {"not_an_image.png", "plain text, not a PNG\n"},
        {"truncated.png", brick.substr(0, brick.size() / 2)},
        // Issue 48: stb_image decodes a cut JPEG with its missing blocks grey, and said nothing.
        {"truncated.jpg", jpeg.substr(0, jpeg.size() * 3 / 4)},
        {"absurd_size.png", huge},
    };
    for (const auto& [name, bytes] : cases) {
        const auto dir = scratchDirectory() / name;
        std::filesystem::create_directories(dir);
        writeFile(dir / name, bytes);
        writeFile(dir / "scene.json", R"({"materials": {"m": {"diffuse_map": ")" + name + R"("}},
            "objects": [{"mesh": {"primitive": "plane", "size": [2, 2]}, "material": "m"}]})");
        for (const char* technique : {"forward", "deferred"}) {
            const test::ProcessResult result = runExecutable(
                {"render", (dir / "scene.json").string(), "-o", (dir / "out.png").string(), "--technique", technique});
            EXPECT_EQ(result.exitCode, 1) << name << ": " << result.stderrText;
            EXPECT_EQ(std::count(result.stderrText.begin(), result.stderrText.end(), '\n'), 1) << result.stderrText;
            EXPECT_NE(result.stderrText.find((dir / name).string()), std::string::npos) << result.stderrText;
            EXPECT_NE(result.stderrText.find("(diffuse_map of material 'm')"), std::string::npos) << result.stderrText;
            EXPECT_FALSE(std::filesystem::exists(dir / "out.png")) << name;
        }
    }
}

TEST(TextureCli, UnknownGBufferLayoutIsUsageError)
{
    const auto dir = scratchDirectory();
    const test::ProcessResult render = runExecutable({"render", "-o", (dir / "out.png").string(), "--gbuffer", "tiny"});
    EXPECT_EQ(render.exitCode, 2);
    EXPECT_NE(render.stderrText.find("--gbuffer"), std::string::npos) << render.stderrText;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
    const test::ProcessResult bench = runExecutable({"bench", "--gbuffer", "tiny", "--csv", (dir / "b.csv").string()});
    EXPECT_EQ(bench.exitCode, 2);
    EXPECT_FALSE(std::filesystem::exists(dir / "b.csv"));
}

}  // namespace
}  // namespace manylights
