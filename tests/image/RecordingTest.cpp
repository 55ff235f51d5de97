// Recording (render --time-range START:END --fps N -o pattern): the frame times, the output
// names, every frame equal to a single render at its time, shards and --skip-existing giving
// the whole recording's files, and bad command lines (exit 2, nothing written).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "TestSupport.h"
#include "apps/cli/Recording.h"
#include "apps/cli/Shard.h"

namespace manylights {
namespace {

using test::renderPfm;
using test::runCliOrFail;
using test::runExecutable;
using test::scratchDirectory;

TEST(Recording, FrameTimesExcludeTheEnd)
{
    const TimeRange range{1.0, 3.0};
    EXPECT_EQ(recordingFrameCount(range, 30.0), 60);
    EXPECT_DOUBLE_EQ(recordingFrameTime(range, 30.0, 0), 1.0);
    EXPECT_DOUBLE_EQ(recordingFrameTime(range, 30.0, 59), 1.0 + 59.0 / 30.0);
    EXPECT_EQ(recordingFrameCount({0.0, 0.1}, 24.0), 3);  // 2.4 frames: 0, 1/24, 2/24
    EXPECT_EQ(recordingFrameCount({0.0, 0.01}, 1.0), 1);  // always at least the first
}

TEST(Recording, PatternsAndTheirNames)
{
    EXPECT_EQ(formatFramePath("frames/%04d.png", 7), "frames/0007.png");
    EXPECT_EQ(formatFramePath("f%d.pfm", 12345), "f12345.pfm");
    EXPECT_EQ(formatFramePath("100%%-%02d.png", 3), "100%-03.png");
    EXPECT_EQ(checkFramePattern("frames/%04d.png"), "");
    EXPECT_EQ(checkFramePattern("100%%-%d.png"), "");
    EXPECT_NE(checkFramePattern("frames.png"), "");
    EXPECT_NE(checkFramePattern("%d-%d.png"), "");
    EXPECT_NE(checkFramePattern("%s.png"), "");
    EXPECT_NE(checkFramePattern("%4d.png"), "");
    EXPECT_NE(checkFramePattern("%0d.png"), "");
    EXPECT_NE(checkFramePattern("frame%"), "");
}

TEST(Recording, TimeRanges)
{
    TimeRange range;
    EXPECT_EQ(parseTimeRange("0.5:2", range), "");
    EXPECT_DOUBLE_EQ(range.start, 0.5);
    EXPECT_DOUBLE_EQ(range.end, 2.0);
    for (const char* bad : {"2", "2:1", "1:1", "-1:2", "a:2", "0:", ":3", "0:inf", "0:2:3", "0:1e999"})
        EXPECT_NE(parseTimeRange(bad, range), "") << bad;
}

TEST(Recording, EveryFrameIsTheRenderAtItsTime)
{
    const auto dir = scratchDirectory();
    const std::vector<std::string> common{"--size", "64x36", "--technique", "deferred"};
    std::vector<std::string> args{"render", "-o", (dir / "frame_%02d.pfm").string(), "--time-range", "0.5:1.25",
                                  "--fps",  "4"};
    args.insert(args.end(), common.begin(), common.end());
    runCliOrFail(args);
    // 0.5, 0.75, 1.0 (1.25 excluded).
    int written = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        written += entry.path().filename().string().starts_with("frame_");
    EXPECT_EQ(written, 3);
    for (int k = 0; k < 3; ++k) {
        const std::string time = std::to_string(0.5 + 0.25 * k);
        std::vector<std::string> single = common;
        single.insert(single.end(), {"--time", time});
        const Image expected = renderPfm("", dir / "single.pfm", single);
        const Image frame = readPfm(dir / ("frame_0" + std::to_string(k) + ".pfm"));
        // The same program on the same inputs: bit-identical.
        EXPECT_EQ(frame.rgb, expected.rgb) << "frame " << k;
    }
    // The animation moves: consecutive frames differ.
    EXPECT_NE(readPfm(dir / "frame_00.pfm").rgb, readPfm(dir / "frame_01.pfm").rgb);
}

TEST(Recording, Shards)
{
    Shard shard;
    EXPECT_EQ(parseShard("2/3", shard), "");
    EXPECT_EQ(shard.index, 2);
    EXPECT_EQ(shard.count, 3);
    EXPECT_FALSE(shard.has(0));
    EXPECT_TRUE(shard.has(1));
    EXPECT_TRUE(shard.has(4));
    EXPECT_EQ(parseShard("1/1", shard), "");
    EXPECT_TRUE(shard.isWhole());
    for (const char* bad : {"0/3", "4/3", "1/0", "-1/3", "1/-3", "3", "/3", "1/", "a/3", "1/3/5", "1.5/3", " 1/3"})
        EXPECT_NE(parseShard(bad, shard), "") << bad;
}

// A recording split over a job array (docs/cli.md, "On a cluster"): three shards, each its
// own process, write byte for byte the files of the whole recording; --skip-existing then
// renders only the missing frames and leaves the others untouched.
TEST(Recording, ShardsAndSkipExistingGiveTheWholeRecording)
{
    const auto dir = scratchDirectory();
    const std::vector<std::string> common{"render", "--size", "48x27", "--technique", "deferred", "--time-range",
                                          "0:1.25", "--fps",  "4"};
    const auto run = [&](const std::filesystem::path& pattern, const std::vector<std::string>& extra) {
        std::vector<std::string> args = common;
        args.insert(args.end(), {"-o", pattern.string()});
        args.insert(args.end(), extra.begin(), extra.end());
        const test::ProcessResult result = runExecutable(args);
        ASSERT_EQ(result.exitCode, 0) << result.stderrText;
    };
    run(dir / "whole" / "f%02d.png", {});
    for (int shard = 1; shard <= 3; ++shard)
        run(dir / "sharded" / "f%02d.png", {"--shard", std::to_string(shard) + "/3"});
    const auto frame = [&](const char* folder, int k) { return dir / folder / ("f0" + std::to_string(k) + ".png"); };
    for (int k = 0; k < 5; ++k) {
        ASSERT_TRUE(std::filesystem::exists(frame("sharded", k))) << k;
        EXPECT_EQ(test::readFile(frame("sharded", k)), test::readFile(frame("whole", k))) << "frame " << k;
    }
    EXPECT_FALSE(std::filesystem::exists(frame("sharded", 5)));

    // A pre-empted task: frames 1 and 3 missing, frame 0 marked to show it is not redone.
    std::filesystem::remove(frame("sharded", 1));
    std::filesystem::remove(frame("sharded", 3));
    test::writeFile(frame("sharded", 0), "kept");
    run(dir / "sharded" / "f%02d.png", {"--skip-existing"});
    EXPECT_EQ(test::readFile(frame("sharded", 0)), "kept");
    for (int k : {1, 3})
        EXPECT_EQ(test::readFile(frame("sharded", k)), test::readFile(frame("whole", k))) << "frame " << k;
    // Nothing left to do: a success that writes nothing.
    run(dir / "sharded" / "f%02d.png", {"--skip-existing", "--shard", "1/1"});
    EXPECT_EQ(test::readFile(frame("sharded", 0)), "kept");
}

TEST(Recording, BadCommandLinesWriteNothing)
{
    const auto dir = scratchDirectory();
    const std::string pattern = (dir / "f%03d.png").string();
    const std::vector<std::vector<std::string>> bad = {
        {"--time-range", "2:1", "-o", pattern},
        {"--time-range", "0:1", "--fps", "0", "-o", pattern},
        {"--time-range", "0:1", "--fps", "-5", "-o", pattern},
        {"--time-range", "zero:1", "-o", pattern},
        {"--time-range", "0:1", "-o", (dir / "f.png").string()},
        {"--time-range", "0:1", "-o", (dir / "f%s.png").string()},
        {"--time-range", "0:1", "--time", "0.5", "-o", pattern},
        {"--time-range", "0:1", "--stats", (dir / "s.json").string(), "-o", pattern},
        {"--fps", "10", "-o", (dir / "f.png").string()},
        {"--time-range", "0:1", "--shard", "0/3", "-o", pattern},
        {"--time-range", "0:1", "--shard", "4/3", "-o", pattern},
        {"--time-range", "0:1", "--shard", "1/0", "-o", pattern},
        {"--time-range", "0:1", "--shard", "two/3", "-o", pattern},
        {"--shard", "1/2", "-o", (dir / "f.png").string()},
        {"--skip-existing", "-o", (dir / "f.png").string()},
    };
    for (const auto& extra : bad) {
        std::vector<std::string> args{"render", "--size", "32x18"};
        args.insert(args.end(), extra.begin(), extra.end());
        const test::ProcessResult result = runExecutable(args);
        EXPECT_EQ(result.exitCode, 2) << extra[1] << ": " << result.stderrText;
    }
    EXPECT_TRUE(std::filesystem::is_empty(dir));
}

}  // namespace
}  // namespace manylights
