// The one writer of every output (core/AtomicFile.h) and the one reader of every input
// (core/InputFile.h): names within NAME_MAX, several files renamed together or not at all.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "core/AtomicFile.h"
#include "core/Error.h"
#include "core/InputFile.h"
#include "core/Numbers.h"

namespace manylights {
namespace {

namespace fs = std::filesystem;

fs::path freshDirectory(const std::string& name)
{
    const fs::path dir = fs::temp_directory_path() / ("manylights-atomic-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string contents(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

TEST(AtomicFile, TemporaryNamesStayWithinNameMax)
{
    const fs::path longName = fs::path("dir") / (std::string(251, 'a') + ".png");
    const fs::path temporary = temporarySibling(longName);
    EXPECT_EQ(temporary.parent_path(), "dir");
    EXPECT_LE(temporary.filename().string().size(), 255u);
    EXPECT_NE(temporary.filename(), longName.filename());
    EXPECT_EQ(temporarySibling("out.png").filename().string().rfind(".out.png.tmp", 0), 0u);
}

TEST(AtomicFile, ASetIsRenamedTogetherOrNotAtAll)
{
    const fs::path dir = freshDirectory("set");
    {
        std::ofstream(dir / "a.txt") << "old a";
    }
    // The second file cannot be written: the first keeps its old contents, no temporary stays.
    {
        AtomicFileSet files;
        files.stage(dir / "a.txt", "first", "new a");
        EXPECT_THROW(files.stage(dir / "missing" / "b.txt", "second", "new b"), Error);
    }
    EXPECT_EQ(contents(dir / "a.txt"), "old a");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
    // Both can: both appear on commit, not before.
    AtomicFileSet files;
    files.stage(dir / "a.txt", "first", "new a");
    files.stage(dir / "b.txt", "second", "new b");
    EXPECT_EQ(contents(dir / "a.txt"), "old a");
    EXPECT_FALSE(fs::exists(dir / "b.txt"));
    files.commit();
    EXPECT_EQ(contents(dir / "a.txt"), "new a");
    EXPECT_EQ(contents(dir / "b.txt"), "new b");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 2);

    // The rename is the last step that can fail (here: a directory holds the name): the error
    // names the file, the temporaries go, and what was renamed before it stays renamed.
    fs::create_directories(dir / "taken" / "inside");
    AtomicFileSet blocked;
    blocked.stage(dir / "c.txt", "third", "new c");
    blocked.stage(dir / "taken", "fourth", "never");
    try {
        blocked.commit();
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).rfind((dir / "taken").string() + ": cannot write fourth: ", 0), 0u) << e.what();
    }
    EXPECT_EQ(contents(dir / "c.txt"), "new c");
    EXPECT_TRUE(fs::is_directory(dir / "taken"));
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 4);  // a, b, c, taken
    fs::remove_all(dir);
}

TEST(AtomicFile, CheckWritableRefusesDirectoriesAndMissingFolders)
{
    const fs::path dir = freshDirectory("check");
    EXPECT_NO_THROW(checkWritable(dir / "out.png", "image"));
    EXPECT_FALSE(fs::exists(dir / "out.png"));
    EXPECT_THROW(checkWritable(dir, "image"), Error);
    EXPECT_THROW(checkWritable(dir / "missing" / "out.png", "image"), Error);
    createOutputFolder(dir / "made" / "deeper" / "f%03d.png");
    EXPECT_TRUE(fs::is_directory(dir / "made" / "deeper"));
    // A file where the folder would go: the error names the folder.
    std::ofstream(dir / "plain") << "x";
    try {
        createOutputFolder(dir / "plain" / "frames" / "f%03d.png");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).rfind((dir / "plain" / "frames").string() + ": cannot create folder: ", 0), 0u)
            << e.what();
    }
    fs::remove_all(dir);
}

TEST(InputFile, OnlyRegularFilesWithinTheLimit)
{
    const fs::path dir = freshDirectory("input");
    std::ofstream(dir / "scene.json") << "{}";
    EXPECT_EQ(readInputFile(dir / "scene.json", "scene file"), "{}");
    EXPECT_EQ(readInputBytes(dir / "scene.json", "scene file"), (std::vector<unsigned char>{'{', '}'}));
    EXPECT_THROW(readInputBytes("/dev/zero", "texture"), Error);
    EXPECT_EQ(inputFileProblem(dir), "it is a directory");
    EXPECT_EQ(inputFileProblem("/dev/zero"), "not a regular file");
    try {
        readInputFile(dir / "absent.json", "scene file");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()),
                  (dir / "absent.json").string() + ": cannot open scene file: No such file or directory");
    }
    fs::remove_all(dir);
}

TEST(Numbers, OneCheckForEveryTypedNumber)
{
    double value = -1.0;
    EXPECT_EQ(checkNumber("2.5", 0.0, 10.0, value), "");
    EXPECT_EQ(value, 2.5);
    EXPECT_EQ(checkNumber("+3", 0.0, 10.0, value), "");
    EXPECT_EQ(value, 3.0);
    for (const char* bad : {"nan", "inf", "-inf", "", "1e400", "11", "-0.5", "3x", "0x10"})
        EXPECT_EQ(checkNumber(bad, 0.0, 10.0, value), "must be a number from 0 to 10, got '" + std::string(bad) + "'")
            << bad;
    EXPECT_EQ(value, 3.0);  // untouched by a refused text
    EXPECT_EQ(formatNumber(1.0e6), "1e+06");
    EXPECT_EQ(formatNumber(0.001), "0.001");
}

TEST(Error, PrintableLineEscapesControlCharacters)
{
    EXPECT_EQ(printableLine("a\nb\tc\rd\x01"
                            "e\x7f"),
              "a\\nb\\tc\\rd\\x01e\\x7f");
    EXPECT_EQ(printableLine("plain: ünïcode"), "plain: ünïcode");
}

}  // namespace
}  // namespace manylights
