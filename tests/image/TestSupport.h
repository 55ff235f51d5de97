// Helpers for the image tests: scratch directories, running the CLI (in-process for
// renders, as a child process where the exit status and stderr are the point), and
// reading results back.
#pragma once

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "render/output/Image.h"

namespace manylights::test {

// The driver profile (--driver-profile) the image tests render under: the environment's
// MANYLIGHTS_TEST_DRIVER_PROFILE, which CTest sets to `gpu` for the image.gpu. tests
// (tests/CMakeLists.txt); "" (the CLI's `auto`) when unset.
std::string testDriverProfile();

// `args` of a render or bench command line with `--driver-profile testDriverProfile()` added,
// unless they name a profile themselves (or none is set).
std::vector<std::string> withTestDriverProfile(std::vector<std::string> args);

// The test scenes' folder (tests/scenes), with its trailing slash.
inline const std::string kTestScenes = MANYLIGHTS_SOURCE_DIR "/tests/scenes/";

// A fresh directory under the build tree's test-output folder, named after the test (and the
// driver profile, so that both profiles' runs of a test can run at once).
std::filesystem::path scratchDirectory();

void writeFile(const std::filesystem::path& path, const std::string& text);

// The whole of a file's bytes ("" when it cannot be read).
std::string readFile(const std::filesystem::path& path);

// The number of newlines in `text`.
int lineCount(const std::string& text);

// Runs `manylights <args>` (withTestDriverProfile) through runCli in this process; fails the
// test on a non-zero exit.
void runCliOrFail(const std::vector<std::string>& args);

// A test name for a technique parameter: test names allow only letters, digits and '_', so
// "tiled-quads" becomes tiled_quads.
inline std::string techniqueTestName(const ::testing::TestParamInfo<std::string>& param)
{
    std::string name = param.param;
    std::replace(name.begin(), name.end(), '-', '_');
    return name;
}

// Whether pixel (x, y) holds a surface, from the `normal` view (zero where nothing was drawn:
// every drawn normal is a unit vector).
inline bool holdsSurface(const Image& normalView, int x, int y)
{
    const float* n = normalView.pixel(x, y);
    return n[0] != 0.0f || n[1] != 0.0f || n[2] != 0.0f;
}

// Renders `scene` (a path, or "" for the default scene) to the PFM `output` and reads it back.
Image renderPfm(const std::string& scene, const std::filesystem::path& output,
                const std::vector<std::string>& extraArgs = {});

struct ProcessResult {
    int exitCode = -1;
    std::string stderrText;
    std::string stdoutText;
};

// Runs the real executable as a child process (so a crash is seen as a crash), with
// `environment` ("NAME=value ...") added to its environment; `args` withTestDriverProfile.
ProcessResult runExecutable(const std::vector<std::string>& args, const std::string& environment = "");

}  // namespace manylights::test
