// `manylights bench` as scripts meet it: a tiny real sweep through the executable (exit
// status, the CSV's rows and values, the JSON's shape, the SVG plot), its usage errors, and the
// plot's axes.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "TestSupport.h"
#include "apps/cli/SvgPlot.h"

namespace manylights {
namespace {

using test::runExecutable;
using test::scratchDirectory;

std::vector<std::string> split(const std::string& text, char separator)
{
    std::vector<std::string> parts;
    std::stringstream stream(text);
    std::string part;
    while (std::getline(stream, part, separator))
        parts.push_back(part);
    // getline drops a trailing empty field ("a,b," gives two): the CSV's empty last
    // columns must still count.
    if (!text.empty() && text.back() == separator)
        parts.emplace_back();
    return parts;
}

// The lines of a text file whose every line ends in '\n'.
std::vector<std::string> lines(const std::string& text)
{
    std::vector<std::string> result = split(text, '\n');
    if (!result.empty() && result.back().empty())
        result.pop_back();
    return result;
}

std::size_t occurrences(const std::string& text, const std::string& what)
{
    std::size_t count = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size()))
        ++count;
    return count;
}

// Nothing under `dir` at all: no output and no temporary beside it.
void expectEmpty(const std::filesystem::path& dir)
{
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        ADD_FAILURE() << "left behind: " << entry.path();
}

// The whole path users take, kept tiny: two techniques, two light counts, one small size.
TEST(Bench, TinySweepWritesCsvAndPlot)
{
    const auto dir = scratchDirectory();
    const auto csv = dir / "bench.csv";
    const auto svg = dir / "bench.svg";
    const test::ProcessResult result =
        runExecutable({"bench", "--techniques", "forward,deferred", "--lights", "16,64", "--size", "64x36", "--frames",
                       "1", "--warmup", "0", "--count-work", "--csv", csv.string(), "--plot", svg.string()});
    ASSERT_EQ(result.exitCode, 0) << result.stderrText;
    // Not a terminal: one progress line per combination.
    EXPECT_NE(result.stderrText.find("[4/4] deferred 64 lights 64x36: "), std::string::npos) << result.stderrText;

    const std::string csvText = test::readFile(csv);
    ASSERT_FALSE(csvText.empty());
    EXPECT_EQ(csvText.back(), '\n');
    const std::vector<std::string> rows = lines(csvText);
    ASSERT_EQ(rows.size(), 5u) << csvText;  // the header and one row per combination
    const std::vector<std::string> header = split(rows[0], ',');
    const std::vector<std::string> expectedHeader = {"technique",
                                                     "lights",
                                                     "width",
                                                     "height",
                                                     "frames",
                                                     "frame_ms_median",
                                                     "frame_ms_min",
                                                     "frame_ms_max",
                                                     "frame_gpu_ms_median",
                                                     "fragment_invocations",
                                                     "passes",
                                                     "light_evaluations",
                                                     "in_range_pairs",
                                                     "transparent_light_evaluations",
                                                     "pass_timing",
                                                     "warmup_frames",
                                                     "frame_ms_p95",
                                                     "frame_gpu_ms_p95",
                                                     "pass_gpu_ms"};
    ASSERT_EQ(header, expectedHeader);
    const auto column = [&](const std::string& name) {
        return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
    };

    // Sizes, then light counts, then techniques: the order of the sweep.
    const std::vector<std::pair<std::string, std::string>> expectedRows = {
        {"forward", "16"}, {"deferred", "16"}, {"forward", "64"}, {"deferred", "64"}};
    std::map<std::string, std::vector<std::string>> inRangeByLights;
    for (std::size_t r = 0; r < expectedRows.size(); ++r) {
        const std::vector<std::string> row = split(rows[r + 1], ',');
        ASSERT_EQ(row.size(), header.size()) << rows[r + 1];
        EXPECT_EQ(row[column("technique")], expectedRows[r].first);
        EXPECT_EQ(row[column("lights")], expectedRows[r].second);
        EXPECT_EQ(row[column("width")], "64");
        EXPECT_EQ(row[column("height")], "36");
        EXPECT_EQ(row[column("frames")], "1");
        const double median = std::stod(row[column("frame_ms_median")]);
        EXPECT_GT(median, 0.0);
        // With one frame the median is that frame, and so are min and max.
        EXPECT_EQ(row[column("frame_ms_min")], row[column("frame_ms_median")]);
        EXPECT_EQ(row[column("frame_ms_max")], row[column("frame_ms_median")]);
        EXPECT_EQ(row[column("frame_ms_p95")], row[column("frame_ms_median")]);
        EXPECT_FALSE(row[column("passes")].empty());
        // The software profile waits for every pass, the GPU's issues frames back to back
        // (image.gpu.*); --warmup 0 renders none before.
        EXPECT_EQ(row[column("pass_timing")], test::testDriverProfile() == "gpu" ? "gpu" : "wall");
        EXPECT_EQ(row[column("warmup_frames")], "0");
        EXPECT_EQ(split(row[column("pass_gpu_ms")], ';').size(), split(row[column("passes")], ';').size());
        const std::uint64_t evaluations = std::stoull(row[column("light_evaluations")]);
        const std::uint64_t inRange = std::stoull(row[column("in_range_pairs")]);
        EXPECT_GT(inRange, 0u);
        EXPECT_GE(evaluations, inRange) << "no technique can evaluate fewer pairs than are in range";
        inRangeByLights[row[column("lights")]].push_back(row[column("in_range_pairs")]);
    }
    // in_range_pairs depends on the scene and the lights, not on the technique.
    for (const auto& [lights, values] : inRangeByLights) {
        ASSERT_EQ(values.size(), 2u);
        EXPECT_EQ(values[0], values[1]) << lights << " lights";
    }
    // Passes are name:wall_ms:fragment_invocations, joined by ';'; deferred has two, and the
    // display pass of the default look (PBR Neutral and sRGB) follows them.
    EXPECT_EQ(split(split(rows[2], ',')[column("passes")], ';').size(), 3u) << rows[2];

    const std::string plot = test::readFile(svg);
    EXPECT_EQ(plot.rfind("<svg", 0), 0u) << plot.substr(0, 80);
    EXPECT_NE(plot.find("</svg>"), std::string::npos);
    EXPECT_EQ(occurrences(plot, "<polyline"), 2u);  // one line per technique
    EXPECT_NE(plot.find(">forward<"), std::string::npos);
    EXPECT_NE(plot.find(">deferred<"), std::string::npos);
    // No temporaries left beside the outputs.
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
}

// `--fps`: each frame at a new time, so the default scene's moving lights are posed on the GPU
// in every timed frame (its `pose lights` pass); without it every frame is at time 0, posed
// once when the renderer was made, and no frame has the pass.
TEST(Bench, FpsPosesTheMovingLightsInEveryFrame)
{
    const auto dir = scratchDirectory();
    for (const bool animate : {false, true}) {
        const auto csv = dir / (animate ? "moving.csv" : "still.csv");
        std::vector<std::string> args = {"bench", "--techniques", "clustered", "--size", "64x36",     "--frames",
                                         "2",     "--warmup",     "1",         "--csv",  csv.string()};
        if (animate)
            args.insert(args.end(), {"--fps", "10"});
        const test::ProcessResult result = runExecutable(args);
        ASSERT_EQ(result.exitCode, 0) << result.stderrText;
        const std::vector<std::string> rows = lines(test::readFile(csv));
        ASSERT_EQ(rows.size(), 2u);
        const std::vector<std::string> header = split(rows[0], ',');
        const std::vector<std::string> row = split(rows[1], ',');
        ASSERT_EQ(row.size(), header.size()) << rows[1];
        const auto passes =
            static_cast<std::size_t>(std::find(header.begin(), header.end(), "passes") - header.begin());
        EXPECT_EQ(occurrences(row[passes], "pose lights:"), animate ? 1u : 0u) << rows[1];
    }
}

// --pass-timing gpu: the frames are issued back to back and timed by the GL's timer queries
// (docs/performance.md, "Timing on a GPU"), which the table and the CSV say; the passes have
// GPU times and no wall times. --warmup auto (the default) renders frames until their time
// settles: at least two here, the first of which compiles the programs.
TEST(Bench, GpuPassTimingIssuesFramesBackToBackAndSaysSo)
{
    const auto dir = scratchDirectory();
    const auto csv = dir / "gpu.csv";
    const test::ProcessResult result = runExecutable({"bench", "--techniques", "clustered", "--size", "64x36",
                                                      "--frames", "3", "--pass-timing", "gpu", "--csv", csv.string()});
    ASSERT_EQ(result.exitCode, 0) << result.stderrText;
    EXPECT_NE(result.stdoutText.find("Pass timing gpu: frames issued back to back"), std::string::npos)
        << result.stdoutText;
    EXPECT_NE(result.stdoutText.find("passes (median gpu ms)"), std::string::npos) << result.stdoutText;
    const std::vector<std::string> rows = lines(test::readFile(csv));
    ASSERT_EQ(rows.size(), 2u);
    const std::vector<std::string> header = split(rows[0], ',');
    const std::vector<std::string> row = split(rows[1], ',');
    ASSERT_EQ(row.size(), header.size()) << rows[1];
    const auto column = [&](const std::string& name) {
        return row[static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin())];
    };
    EXPECT_EQ(column("pass_timing"), "gpu");
    EXPECT_GE(std::stoi(column("warmup_frames")), 2);
    EXPECT_GT(std::stod(column("frame_ms_median")), 0.0);
    EXPECT_GE(std::stod(column("frame_ms_p95")), std::stod(column("frame_ms_median")));
    // name::invocations (no wall time) per pass, and name:gpu_ms beside it.
    for (const std::string& pass : split(column("passes"), ';'))
        EXPECT_NE(pass.find("::"), std::string::npos) << pass;
    for (const std::string& pass : split(column("pass_gpu_ms"), ';'))
        EXPECT_GE(std::stod(pass.substr(pass.rfind(':') + 1)), 0.0) << pass;
}

// --json (docs/cli.md, "JSON"), what scripts/lib/bench.py reads: the sweep's header (the GL
// renderer, the driver profile, the pass timing) and one object per combination in sweep order,
// each pass with its median on the clock the frames were timed with, named: under wall the
// pass's wall time, under gpu its GL_TIME_ELAPSED, under frame none. `--json -` writes it to
// stdout alone, the table then on stderr.
TEST(Bench, JsonNamesEachPassClock)
{
    const auto dir = scratchDirectory();
    const std::string timing = test::testDriverProfile() == "gpu" ? "gpu" : "wall";
    for (const std::string& passTiming : {timing, std::string("frame")}) {
        SCOPED_TRACE(passTiming);
        const bool toStdout = passTiming != "frame";
        const auto file = dir / (passTiming + ".json");
        std::vector<std::string> args = {"bench",
                                         "--techniques",
                                         "forward,clustered",
                                         "--lights",
                                         "16",
                                         "--size",
                                         "64x36",
                                         "--frames",
                                         "1",
                                         "--warmup",
                                         "0",
                                         "--count-work",
                                         "--json",
                                         toStdout ? "-" : file.string()};
        if (!toStdout)
            args.insert(args.end(), {"--pass-timing", "frame"});
        const test::ProcessResult result = runExecutable(args);
        ASSERT_EQ(result.exitCode, 0) << result.stderrText;
        const std::string& tableStream = toStdout ? result.stderrText : result.stdoutText;
        EXPECT_NE(tableStream.find("technique  lights"), std::string::npos) << tableStream;
        const std::string text = toStdout ? result.stdoutText : test::readFile(file);
        ASSERT_FALSE(text.empty());
        const nlohmann::json json = nlohmann::json::parse(text);  // throws, and fails the test, unless it is JSON

        EXPECT_EQ(json.at("pass_timing"), passTiming);
        EXPECT_EQ(json.at("driver_profile"), test::testDriverProfile() == "gpu" ? "gpu" : "software");
        EXPECT_EQ(json.at("frames"), 1);
        EXPECT_EQ(json.at("warmup"), 0);
        const std::string renderer = json.at("gl_renderer");
        EXPECT_FALSE(renderer.empty());
        EXPECT_EQ(json.at("device").get<std::string>().rfind(renderer, 0), 0u) << "device names the GL renderer first";
        const nlohmann::json& results = json.at("results");
        ASSERT_EQ(results.size(), 2u);
        EXPECT_EQ(results[0].at("technique"), "forward");
        EXPECT_EQ(results[1].at("technique"), "clustered");
        for (const nlohmann::json& r : results) {
            EXPECT_EQ(r.at("lights"), 16);
            EXPECT_EQ(r.at("width"), 64);
            EXPECT_EQ(r.at("height"), 36);
            EXPECT_EQ(r.at("frames"), 1);
            EXPECT_EQ(r.at("warmup_frames"), 0);
            EXPECT_EQ(r.at("pass_timing"), passTiming);
            EXPECT_TRUE(r.at("lighting_stage") == "fragment" || r.at("lighting_stage") == "compute") << r;
            // One frame: its time is the median, p95, min and max.
            const nlohmann::json& frame = r.at("frame_ms");
            EXPECT_GT(frame.at("median").get<double>(), 0.0);
            for (const char* statistic : {"p95", "min", "max"})
                EXPECT_EQ(frame.at(statistic), frame.at("median")) << statistic;
            EXPECT_TRUE(r.at("frame_gpu_ms").at("median").is_number());
            ASSERT_FALSE(r.at("passes").empty());
            for (const nlohmann::json& pass : r.at("passes")) {
                EXPECT_FALSE(pass.at("name").get<std::string>().empty());
                if (passTiming == "frame") {
                    EXPECT_TRUE(pass.at("clock").is_null()) << pass;
                    EXPECT_TRUE(pass.at("ms").is_null()) << pass;
                    continue;
                }
                EXPECT_EQ(pass.at("clock"), passTiming) << pass;
                EXPECT_GE(pass.at("ms").get<double>(), 0.0) << pass;
                EXPECT_EQ(pass.at("ms"), pass.at(passTiming + "_ms")) << pass;
            }
            EXPECT_TRUE(r.at("counters").is_object());
            const nlohmann::json& work = r.at("work");
            EXPECT_GT(work.at("in_range_pairs").get<std::uint64_t>(), 0u);
            EXPECT_GE(work.at("light_evaluations").get<std::uint64_t>(),
                      work.at("in_range_pairs").get<std::uint64_t>());
        }
        // The pairs in range are the scene's, whichever technique counts them.
        EXPECT_EQ(results[0].at("work").at("in_range_pairs"), results[1].at("work").at("in_range_pairs"));
        // clustered reports what its lists held (render --stats' counters).
        EXPECT_TRUE(results[1].at("counters").contains("cluster_pairs")) << results[1].at("counters");
    }
}

// Issue 47: bench takes --shadow-lights N|all (the scene's "shadow_lights" where not given),
// --shadow-pool-mib and --rebuild-shadows as render does, and its JSON says what it ran with.
// --rebuild-shadows reaches the renderer: the timed frame after the warm-up draws shadows only
// with it, since without it a still scene's second frame reuses what the first drew (issue 47
// item 4). One light at 32x18, one frame.
TEST(Bench, ShadowOptionsReachTheRendererAndTheJson)
{
    const auto dir = scratchDirectory();
    const auto scene = dir / "scene.json";
    test::writeFile(scene, R"({"shadow_lights": 2,
        "lights": [{"type": "point", "pos": [0, 1, 0], "intensity": [1, 1, 1], "range": 3}],
        "objects": [{"mesh": {"primitive": "plane", "size": [2, 2]}}]})");
    const auto bench = [&](const std::vector<std::string>& options) {
        std::vector<std::string> args{"bench",        scene.string(),
                                      "--techniques", "forward",
                                      "--size",       "32x18",
                                      "--frames",     "1",
                                      "--warmup",     "1",
                                      "--json",       "-"};
        args.insert(args.end(), options.begin(), options.end());
        const test::ProcessResult result = runExecutable(args);
        EXPECT_EQ(result.exitCode, 0) << result.stderrText;
        return nlohmann::json::parse(result.stdoutText);
    };
    const auto drawsShadows = [](const nlohmann::json& sweep) {
        const nlohmann::json& passes = sweep.at("results").at(0).at("passes");
        return std::any_of(passes.begin(), passes.end(), [](const nlohmann::json& pass) {
            return pass.at("name").get<std::string>().rfind("shadow", 0) == 0;
        });
    };
    const nlohmann::json scenes = bench({});
    EXPECT_EQ(scenes.at("shadow_lights"), 2);
    EXPECT_EQ(scenes.at("shadow_pool_mib"), 256);
    EXPECT_EQ(scenes.at("rebuild_shadows"), false);
    EXPECT_FALSE(drawsShadows(scenes)) << scenes.at("results");

    const nlohmann::json rebuilt = bench({"--shadow-lights", "all", "--shadow-pool-mib", "12", "--rebuild-shadows"});
    EXPECT_EQ(rebuilt.at("shadow_lights"), "all");
    EXPECT_EQ(rebuilt.at("shadow_pool_mib"), 12);
    EXPECT_EQ(rebuilt.at("rebuild_shadows"), true);
    ASSERT_EQ(rebuilt.at("results").size(), 1u);
    EXPECT_TRUE(drawsShadows(rebuilt)) << rebuilt.at("results");
}

// --json and --csv naming one file would write one over the other.
TEST(Bench, JsonAndCsvNamingOneFileIsAUsageError)
{
    const auto dir = scratchDirectory();
    const std::string path = (dir / "out.txt").string();
    const test::ProcessResult result =
        runExecutable({"bench", "--size", "16x16", "--frames", "1", "--csv", path, "--json", path});
    EXPECT_EQ(result.exitCode, 2) << result.stderrText;
    EXPECT_NE(result.stderrText.find("--csv and --json name the same file"), std::string::npos) << result.stderrText;
    expectEmpty(dir);
}

// A job array's tasks (docs/cli.md, "On a cluster"): three shards of a four-case sweep, each
// its own process, time each case once; only shard 1's CSV has the header, so the CSVs
// concatenate into one valid CSV with the whole sweep's rows.
TEST(Bench, ShardsSplitTheCasesAndTheirCsvsConcatenate)
{
    const auto dir = scratchDirectory();
    std::string concatenated;
    std::vector<std::size_t> rowsPerShard;
    for (int shard = 1; shard <= 3; ++shard) {
        const auto csv = dir / ("shard" + std::to_string(shard) + ".csv");
        const test::ProcessResult result = runExecutable(
            {"bench", "--techniques", "forward,deferred", "--lights", "16,64", "--size", "32x18", "--frames", "1",
             "--warmup", "0", "--shard", std::to_string(shard) + "/3", "--csv", csv.string()});
        ASSERT_EQ(result.exitCode, 0) << result.stderrText;
        const std::string text = test::readFile(csv);
        rowsPerShard.push_back(lines(text).size());
        concatenated += text;
    }
    // Cases in sweep order: forward 16, deferred 16, forward 64, deferred 64; shard I takes
    // those with number mod 3 = I - 1 (shard 1 also writes the header).
    EXPECT_EQ(rowsPerShard, (std::vector<std::size_t>{3, 1, 1}));
    const std::vector<std::string> rows = lines(concatenated);
    ASSERT_EQ(rows.size(), 5u) << concatenated;
    EXPECT_TRUE(rows[0].starts_with("technique,lights,")) << rows[0];
    std::vector<std::string> cases;
    for (std::size_t r = 1; r < rows.size(); ++r) {
        const std::vector<std::string> row = split(rows[r], ',');
        ASSERT_EQ(row.size(), split(rows[0], ',').size()) << rows[r];
        cases.push_back(row[0] + " " + row[1]);
    }
    EXPECT_EQ(cases, (std::vector<std::string>{"forward 16", "deferred 64", "deferred 16", "forward 64"}));
}

struct UsageCase {
    std::string name;
    std::vector<std::string> args;
    std::string phrase;
    friend void PrintTo(const UsageCase& c, std::ostream* os) { *os << c.name; }
};

class BenchUsage : public ::testing::TestWithParam<UsageCase> {};

// A bad command line exits 2 before anything runs, so nothing is written.
TEST_P(BenchUsage, ExitsTwoAndWritesNothing)
{
    const UsageCase& c = GetParam();
    const auto dir = scratchDirectory();
    std::vector<std::string> args = {"bench",
                                     "--size",
                                     "16x16",
                                     "--frames",
                                     "1",
                                     "--warmup",
                                     "0",
                                     "--csv",
                                     (dir / "out.csv").string(),
                                     "--plot",
                                     (dir / "out.svg").string()};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const test::ProcessResult result = runExecutable(args);
    EXPECT_EQ(result.exitCode, 2) << result.stderrText;
    EXPECT_NE(result.stderrText.find(c.phrase), std::string::npos) << result.stderrText;
    expectEmpty(dir);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, BenchUsage,
    ::testing::Values(UsageCase{"lights_not_a_number", {"--lights", "abc"}, "--lights"},
                      UsageCase{"shadow_lights_negative", {"--shadow-lights", "-2"}, "--shadow-lights"},
                      UsageCase{"shadow_lights_not_a_number", {"--shadow-lights", "x"}, "--shadow-lights"},
                      UsageCase{"shadow_lights_fraction", {"--shadow-lights", "1.5"}, "--shadow-lights"},
                      UsageCase{"shadow_pool_zero", {"--shadow-pool-mib", "0"}, "--shadow-pool-mib"},
                      UsageCase{"shadow_pool_off_the_grain", {"--shadow-pool-mib", "6"}, "from 4 to 1024"},
                      UsageCase{"shadow_pool_too_large", {"--shadow-pool-mib", "1028"}, "--shadow-pool-mib"},
                      UsageCase{"shadow_pool_nan", {"--shadow-pool-mib", "nan"}, "--shadow-pool-mib"},
                      UsageCase{"lights_one_bad_entry", {"--lights", "16,x"}, "--lights"},
                      UsageCase{"lights_negative", {"--lights", "16,-4"}, "--lights"},
                      UsageCase{"lights_repeated", {"--lights", "16,16"}, "lists 16 twice"},
                      UsageCase{"unknown_technique", {"--techniques", "nope"}, "nope"},
                      UsageCase{"one_unknown_technique", {"--techniques", "forward,nope"}, "nope"},
                      UsageCase{"malformed_size", {"--size", "64x36,big"}, "--size"},
                      UsageCase{"zero_frames", {"--frames", "0"}, "--frames"},
                      UsageCase{"negative_warmup", {"--warmup", "-1"}, "--warmup"},
                      UsageCase{"fps_zero", {"--fps", "0"}, "--fps"},
                      UsageCase{"fps_not_a_number", {"--fps", "nan"}, "--fps"},
                      UsageCase{"plot_not_svg", {"--plot", "plot.png"}, "--plot"},
                      UsageCase{"shard_zero", {"--shard", "0/3"}, "--shard"},
                      UsageCase{"shard_past_the_count", {"--shard", "4/3"}, "--shard"},
                      UsageCase{"shard_of_none", {"--shard", "1/0"}, "--shard"},
                      UsageCase{"shard_not_a_fraction", {"--shard", "2"}, "--shard"},
                      UsageCase{"shard_with_plot", {"--shard", "1/2"}, "--shard does not combine"}),
    [](const ::testing::TestParamInfo<UsageCase>& param) { return param.param.name; });

// Like render: a scene problem is one line on stderr, exit 1, and no file written.
TEST(Bench, BadSceneIsOneLineExitOne)
{
    const auto dir = scratchDirectory();
    const auto scene = dir / "scene.json";
    test::writeFile(scene, "{\"ambient\": [0, 0\n");
    const auto out = dir / "out";
    std::filesystem::create_directory(out);
    const test::ProcessResult result = runExecutable({"bench", scene.string(), "--size", "16x16", "--csv",
                                                      (out / "b.csv").string(), "--plot", (out / "b.svg").string()});
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_EQ(std::count(result.stderrText.begin(), result.stderrText.end(), '\n'), 1) << result.stderrText;
    EXPECT_NE(result.stderrText.find("scene.json:"), std::string::npos) << result.stderrText;
    expectEmpty(out);
}

// The culling's settings from the environment are read and checked by bench as by render
// (apps/cli/CommandSupport.h cullingTuningFromEnvironment; render's cases: GlobalLightsTest.cpp):
// one line naming the variable, exit 1, and neither output written.
TEST(Bench, ABadCullingSettingIsOneLineExitOneBeforeAnyOutput)
{
    const auto out = scratchDirectory() / "out";
    std::filesystem::create_directory(out);
    const std::vector<std::string> args = {
        "bench", "--techniques", "tiled-quads", "--size", "16x16", "--frames", "1", "--csv", (out / "b.csv").string()};
    const test::ProcessResult result = runExecutable(args, "MANYLIGHTS_CULLING_THREADS=0");
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_EQ(std::count(result.stderrText.begin(), result.stderrText.end(), '\n'), 1) << result.stderrText;
    EXPECT_NE(result.stderrText.find("MANYLIGHTS_CULLING_THREADS: expected a whole number of threads"),
              std::string::npos)
        << result.stderrText;
    expectEmpty(out);
    EXPECT_EQ(runExecutable(args, "MANYLIGHTS_CULLING_THREADS=2").exitCode, 0);
}

TEST(Bench, LightsNeedLightSets)
{
    const auto dir = scratchDirectory();
    const auto scene = dir / "scene.json";
    test::writeFile(scene, R"({"objects": [{"mesh": {"primitive": "plane", "size": [2, 2]}}]})");
    const test::ProcessResult result = runExecutable({"bench", scene.string(), "--lights", "4", "--size", "16x16"});
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.stderrText.find("light_sets"), std::string::npos) << result.stderrText;
}

// An output that cannot be written fails before the sweep, not after hours of it.
TEST(Bench, UnwritableCsvFailsFirst)
{
    const auto dir = scratchDirectory();
    const test::ProcessResult result =
        runExecutable({"bench", "--size", "16x16", "--csv", (dir / "missing" / "b.csv").string()});
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.stderrText.find("b.csv"), std::string::npos) << result.stderrText;
    EXPECT_EQ(result.stderrText.find("[1/"), std::string::npos) << "the sweep started: " << result.stderrText;
}

// --- the plot's axes, without GL ---------------------------------------------------------

TEST(SvgPlot, DecadeRangeCoversTheValues)
{
    EXPECT_EQ(decadeRange(256, 65536).first, 2);
    EXPECT_EQ(decadeRange(256, 65536).last, 5);
    // Exact powers of ten do not widen the axis by an empty decade.
    EXPECT_EQ(decadeRange(1000, 100000).first, 3);
    EXPECT_EQ(decadeRange(1000, 100000).last, 5);
    EXPECT_EQ(decadeRange(0.05, 0.3).first, -2);
    EXPECT_EQ(decadeRange(0.05, 0.3).last, 0);
    // One value still gets a decade.
    EXPECT_EQ(decadeRange(100, 100).first, 2);
    EXPECT_EQ(decadeRange(100, 100).last, 3);
}

TEST(SvgPlot, DecadeLabels)
{
    EXPECT_EQ(decadeLabel(0), "1");
    EXPECT_EQ(decadeLabel(3), "1000");
    EXPECT_EQ(decadeLabel(4), "10k");
    EXPECT_EQ(decadeLabel(5), "100k");
    EXPECT_EQ(decadeLabel(6), "1M");
    EXPECT_EQ(decadeLabel(-1), "0.1");
    EXPECT_EQ(decadeLabel(-3), "0.001");
    EXPECT_EQ(decadeLabel(-4), "1e-4");
    EXPECT_EQ(decadeLabel(12), "1e12");
}

TEST(SvgPlot, OnePanelPerSizeOneLinePerSeries)
{
    LogLogPlot plot;
    plot.xLabel = "lights";
    plot.yLabel = "ms";
    for (const char* title : {"a <small> & wide", "b"}) {
        PlotPanel panel;
        panel.title = title;
        for (std::size_t s = 0; s < 3; ++s)
            panel.series.push_back({"series" + std::to_string(s),
                                    paletteColour(s),
                                    {{256, 10.0 + static_cast<double>(s), 9.0, 12.0, "note"},
                                     {4096, 100.0, 100.0, 100.0, ""},
                                     {0, 5.0, 5.0, 5.0, ""}}});  // x = 0 is left out
        plot.panels.push_back(panel);
    }
    const std::string svg = logLogSvg(plot);
    EXPECT_EQ(svg.rfind("<svg", 0), 0u);
    EXPECT_EQ(occurrences(svg, "<polyline"), 6u);
    EXPECT_EQ(occurrences(svg, "<g transform="), 2u);
    EXPECT_NE(svg.find("a &lt;small&gt; &amp; wide"), std::string::npos);  // escaped
    // Decade labels of both axes: lights 100 to 10k, times 1 to 1000.
    for (const char* label : {">100<", ">1000<", ">10k<", ">1<", ">10<"})
        EXPECT_NE(svg.find(label), std::string::npos) << label;
    EXPECT_EQ(svg.find("nan"), std::string::npos);
    EXPECT_EQ(svg.find("inf"), std::string::npos);
    EXPECT_NE(paletteColour(0), paletteColour(1));
}

}  // namespace
}  // namespace manylights
