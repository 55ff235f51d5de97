// What a hostile-input run found, one test per class (docs/cli.md, "Exit status"): failed
// writes reported and the old file kept, outputs all or nothing, every number checked, no
// crash or hang on deep nesting, FIFOs or long names, and one-line messages whatever a file is
// called. Run as child processes (a crash or a hang shows as one: `timeout` bounds each).
#include <gtest/gtest.h>

#include <sys/stat.h>

#include "TestSupport.h"

namespace manylights {
namespace {

using test::runExecutable;
using test::scratchDirectory;
using test::writeFile;

// Every child runs under `timeout`, so that a hang fails the test instead of blocking it.
constexpr const char* kBounded = "timeout 60";

// The first line of stderr (CLI11 adds "Run with --help" after a usage error).
std::string firstLine(const std::string& text) { return text.substr(0, text.find('\n')); }

// A PNG already there, to check that a failure leaves it alone.
std::string renderOld(const std::filesystem::path& path)
{
    const test::ProcessResult made = runExecutable({"render", "-o", path.string(), "--size", "16x9"}, kBounded);
    EXPECT_EQ(made.exitCode, 0) << made.stderrText;
    return test::readFile(path);
}

TEST(Hardening, AFailedPngWriteIsExitOneAndKeepsTheOldFile)
{
    const auto dir = scratchDirectory();
    const std::string old = renderOld(dir / "old.png");
    // 4 KiB of file size: a 320x180 PNG of the default scene needs far more. Without the
    // checked writer stb_image_write ignored the short write and the run exited 0.
    const test::ProcessResult result =
        runExecutable({"render", "-o", (dir / "old.png").string(), "--size", "320x180"}, "ulimit -f 4 &&");
    EXPECT_EQ(result.exitCode, 1) << result.stderrText;
    EXPECT_EQ(test::lineCount(result.stderrText), 1) << result.stderrText;
    EXPECT_NE(result.stderrText.find("old.png: cannot write image: File too large"), std::string::npos)
        << result.stderrText;
    EXPECT_EQ(test::readFile(dir / "old.png"), old);
    for (const auto& entry : std::filesystem::directory_iterator(dir))
        EXPECT_EQ(entry.path().filename(), "old.png") << "left behind: " << entry.path();
}

TEST(Hardening, OutputsAreAllOrNothing)
{
    const auto dir = scratchDirectory();
    const std::string old = renderOld(dir / "out.png");
    std::filesystem::create_directory(dir / "a-directory");
    for (const std::filesystem::path& stats :
         {std::filesystem::path("/proc/manylights-stats.json"), dir / "missing" / "s.json", dir / "a-directory"}) {
        const test::ProcessResult result = runExecutable(
            {"render", "-o", (dir / "out.png").string(), "--stats", stats.string(), "--size", "32x18"}, kBounded);
        EXPECT_EQ(result.exitCode, 1) << stats << ": " << result.stderrText;
        EXPECT_EQ(test::lineCount(result.stderrText), 1) << result.stderrText;
        EXPECT_NE(result.stderrText.find("cannot write statistics"), std::string::npos) << result.stderrText;
        EXPECT_EQ(test::readFile(dir / "out.png"), old) << stats;
    }
}

TEST(Hardening, StatsAndImageMayNotBeOneFile)
{
    const auto dir = scratchDirectory();
    const std::string out = (dir / "out.png").string();
    const std::string sameByAnotherName = (dir / "." / "out.png").string();
    const test::ProcessResult result = runExecutable({"render", "-o", out, "--stats", sameByAnotherName}, kBounded);
    EXPECT_EQ(result.exitCode, 2) << result.stderrText;
    EXPECT_NE(result.stderrText.find("name the same file"), std::string::npos) << result.stderrText;
    EXPECT_FALSE(std::filesystem::exists(out));
    const test::ProcessResult bench =
        runExecutable({"bench", "--csv", (dir / "x.svg").string(), "--plot", (dir / "x.svg").string()}, kBounded);
    EXPECT_EQ(bench.exitCode, 2) << bench.stderrText;
}

TEST(Hardening, LongNamesAndUpperCaseExtensionsAreOutputs)
{
    const auto dir = scratchDirectory();
    // 254 bytes: legal (NAME_MAX is 255); the temporary beside it must be too.
    const std::string longName = std::string(250, 'a') + ".png";
    for (const std::string& name : {longName, std::string("OUT.PNG"), std::string("out.Pfm")}) {
        const test::ProcessResult result =
            runExecutable({"render", "-o", (dir / name).string(), "--size", "16x9"}, kBounded);
        EXPECT_EQ(result.exitCode, 0) << name << ": " << result.stderrText;
        EXPECT_TRUE(std::filesystem::exists(dir / name)) << name;
    }
    EXPECT_EQ(test::readFile(dir / "OUT.PNG").substr(1, 3), "PNG");
    EXPECT_EQ(test::readFile(dir / "out.Pfm").substr(0, 2), "PF");
}

struct NumberCase {
    std::vector<std::string> args;
    std::string option;  // named in the message
};

TEST(Hardening, EveryNumericOptionIsFiniteAndInRange)
{
    const auto dir = scratchDirectory();
    const std::string out = (dir / "out.png").string();
    const std::string frames = (dir / "f%03d.png").string();
    const std::vector<NumberCase> cases = {
        {{"render", "-o", out, "--time", "nan"}, "--time"},
        {{"render", "-o", out, "--time", "inf"}, "--time"},
        {{"render", "-o", out, "--time", "-1"}, "--time"},
        {{"render", "-o", out, "--time", "1e300"}, "--time"},
        {{"render", "-o", frames, "--time-range", "0:1", "--fps", "nan"}, "--fps"},
        {{"render", "-o", frames, "--time-range", "0:1e10", "--fps", "1000"}, "--time-range"},
        {{"render", "-o", frames, "--time-range", "1e300:1e301"}, "--time-range"},
        {{"render", "-o", frames, "--time-range", "0:999999", "--fps", "1000"}, "frames"},
        {{"bench", "--budget-ms", "nan"}, "--budget-ms"},
        {{"view", "--time", "nan"}, "--time"},
    };
    for (const NumberCase& c : cases) {
        const test::ProcessResult result = runExecutable(c.args, kBounded);
        EXPECT_EQ(result.exitCode, 2) << c.args.back() << ": " << result.stderrText;
        const std::string line = firstLine(result.stderrText);
        EXPECT_NE(line.find(c.option), std::string::npos) << line;
        // Limits printed readably: DBL_MAX in full was 309 digits.
        EXPECT_LT(line.size(), 160u) << line;
    }
    EXPECT_FALSE(std::filesystem::exists(out));
    EXPECT_FALSE(std::filesystem::exists(dir / "f000.png"));
}

TEST(Hardening, DeeplyNestedGltfIsAnErrorNotACrash)
{
    const auto dir = scratchDirectory();
    constexpr int kDepth = 20000;  // tinygltf's recursion overflowed the stack here
    writeFile(dir / "deep.gltf", R"({"asset": {"version": "2.0", "extras": )" + std::string(kDepth, '[') +
                                     std::string(kDepth, ']') + "}}");
    writeFile(dir / "scene.json", R"({"objects": [{"mesh": "deep.gltf"}]})");
    const test::ProcessResult result =
        runExecutable({"render", (dir / "scene.json").string(), "-o", (dir / "out.png").string()}, kBounded);
    EXPECT_EQ(result.exitCode, 1) << result.stderrText;
    EXPECT_EQ(test::lineCount(result.stderrText), 1) << result.stderrText;
    EXPECT_NE(result.stderrText.find("deep.gltf:1:"), std::string::npos) << result.stderrText;
    EXPECT_NE(result.stderrText.find("nested deeper than"), std::string::npos) << result.stderrText;
}

TEST(Hardening, OnlyRegularFilesAreRead)
{
    const auto dir = scratchDirectory();
    ASSERT_EQ(::mkfifo((dir / "fifo.json").c_str(), 0600), 0);
    for (const std::string& scene : {(dir / "fifo.json").string(), std::string("/dev/zero")}) {
        const test::ProcessResult result = runExecutable({"render", scene, "-o", (dir / "out.png").string()}, kBounded);
        EXPECT_EQ(result.exitCode, 1) << scene << ": " << result.stderrText;
        EXPECT_NE(result.stderrText.find(scene + ": cannot open scene file: not a regular file"), std::string::npos)
            << result.stderrText;
    }
    // A glTF buffer that is a FIFO blocked for ever.
    ASSERT_EQ(::mkfifo((dir / "buffer.bin").c_str(), 0600), 0);
    writeFile(dir / "model.gltf", R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "buffer.bin", "byteLength": 36}],
        "bufferViews": [{"buffer": 0, "byteLength": 36}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 0]}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}], "nodes": [{"mesh": 0}],
        "scenes": [{"nodes": [0]}]})");
    writeFile(dir / "scene.json", R"({"objects": [{"mesh": "model.gltf"}]})");
    const test::ProcessResult result =
        runExecutable({"render", (dir / "scene.json").string(), "-o", (dir / "out.png").string()}, kBounded);
    EXPECT_EQ(result.exitCode, 1) << result.stderrText;
    EXPECT_NE(result.stderrText.find("not a regular file"), std::string::npos) << result.stderrText;
}

TEST(Hardening, AnUnknownNameAmongLongNamesFailsAtOnce)
{
    // The guess ("did you mean") costs the product of the lengths of the name and of each
    // candidate, so it now compares names of at most 64 bytes: a 600 KB file of long names hung
    // the loader. Seen from outside: a one-letter typo of a 10,000-byte name gets no guess (the
    // old loader, after seconds of work, guessed it), and the line still names the key.
    const auto dir = scratchDirectory();
    std::string materials;
    for (int i = 0; i < 60; ++i)
        materials += (i ? ", " : "") + std::string("\"") + std::string(10000, static_cast<char>('a' + i % 26)) +
                     std::to_string(i) + R"(": {"diffuse": [1, 1, 1]})";
    const std::string typo = std::string(9999, 'a') + "b0";  // materials' first name, one letter off
    writeFile(dir / "scene.json", "{\"materials\": {" + materials +
                                      R"(}, "objects": [{"mesh": {"primitive": "sphere", "radius": 1}, "material": ")" +
                                      typo + "\"}]}");
    const test::ProcessResult result =
        runExecutable({"render", (dir / "scene.json").string(), "-o", (dir / "out.png").string()}, kBounded);
    EXPECT_EQ(result.exitCode, 1) << result.stderrText.substr(0, 200);
    EXPECT_EQ(test::lineCount(result.stderrText), 1);
    EXPECT_NE(result.stderrText.find("/objects/0/material"), std::string::npos) << result.stderrText.substr(0, 200);
    EXPECT_EQ(result.stderrText.find("did you mean"), std::string::npos) << result.stderrText.substr(0, 200);
    // A short typo is still guessed.
    writeFile(dir / "short.json", R"({"materials": {"marble": {}}, "objects": [{"mesh": {"primitive": "sphere",
        "radius": 1}, "material": "marbel"}]})");
    const test::ProcessResult guessed =
        runExecutable({"render", (dir / "short.json").string(), "-o", (dir / "out.png").string()}, kBounded);
    EXPECT_NE(guessed.stderrText.find("did you mean 'marble'"), std::string::npos) << guessed.stderrText;
}

TEST(Hardening, ControlCharactersInNamesAreEscapedInTheOneLine)
{
    const auto dir = scratchDirectory();
    const test::ProcessResult result =
        runExecutable({"render", (dir / "new\nline.json").string(), "-o", (dir / "out.png").string()}, kBounded);
    EXPECT_EQ(result.exitCode, 1) << result.stderrText;
    EXPECT_EQ(test::lineCount(result.stderrText), 1) << result.stderrText;
    EXPECT_NE(result.stderrText.find("new\\nline.json"), std::string::npos) << result.stderrText;
}

TEST(Hardening, AnImageTooLargeForMemoryIsExitOne)
{
#if defined(__SANITIZE_ADDRESS__)
    GTEST_SKIP() << "AddressSanitizer reserves more address space than the limit this test sets";
#else
    const auto dir = scratchDirectory();
    // 8 GB of address space: a 16384x16384 frame's targets need about 13 GB.
    const test::ProcessResult result = runExecutable(
        {"render", "-o", (dir / "out.png").string(), "--size", "16384x16384"}, "ulimit -v 8000000 && timeout 120");
    EXPECT_EQ(result.exitCode, 1) << result.stderrText;
    EXPECT_NE(result.stderrText.find("out of memory"), std::string::npos) << result.stderrText;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
#endif
}

TEST(Hardening, CommandLineConventions)
{
    const auto dir = scratchDirectory();
    // A recording's folder is made, as other tools make theirs.
    const test::ProcessResult recorded = runExecutable({"render", "-o", (dir / "frames" / "f%02d.png").string(),
                                                        "--size", "16x9", "--time-range", "0:0.1", "--fps", "20"},
                                                       kBounded);
    EXPECT_EQ(recorded.exitCode, 0) << recorded.stderrText;
    EXPECT_TRUE(std::filesystem::exists(dir / "frames" / "f01.png"));
    // Not a terminal: the progress is plain lines, without carriage returns.
    EXPECT_EQ(recorded.stderrText.find('\r'), std::string::npos) << recorded.stderrText;
    EXPECT_NE(recorded.stderrText.find("recorded 2/2 frames"), std::string::npos) << recorded.stderrText;

    // --version, and --help listing every command (the viewer's too).
    const auto printed = [&](const std::string& option) {
        const std::filesystem::path text = dir / "printed.txt";
        EXPECT_EQ(std::system(("'" MANYLIGHTS_EXE "' " + option + " >'" + text.string() + "'").c_str()), 0) << option;
        return test::readFile(text);
    };
    EXPECT_EQ(printed("--version").rfind("manylights ", 0), 0u);
    const std::string helpText = printed("--help");
    for (const char* command : {"render", "bench", "view"})
        EXPECT_NE(helpText.find(std::string("  ") + command + " "), std::string::npos) << command << "\n" << helpText;
}

}  // namespace
}  // namespace manylights
