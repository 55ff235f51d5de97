// `manylights devices` and --device through the executable (issue 40): the table with its uuid
// column, a device chosen by index or by UUID, and the one-line errors of a device that does
// not exist (exit 1) and of a value that is neither an index nor a UUID (exit 2).
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "TestSupport.h"
#include "platform/EglChoice.h"
#include "platform/HeadlessContext.h"

namespace manylights {
namespace {

using test::runExecutable;
using test::scratchDirectory;

struct DevicesOutput {
    int exitCode = -1;
    std::vector<std::vector<std::string>> rows;  // the header first, each split on runs of spaces
    std::string stderrText;
};

// `manylights devices`, run as a child process for its stdout (runExecutable keeps stderr only).
DevicesOutput runDevices(const std::filesystem::path& dir)
{
    const std::string command =
        "'" MANYLIGHTS_EXE "' devices >'" + (dir / "out.txt").string() + "' 2>'" + (dir / "err.txt").string() + "'";
    const int status = std::system(command.c_str());
    DevicesOutput output;
    output.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    output.stderrText = test::readFile(dir / "err.txt");
    std::istringstream lines(test::readFile(dir / "out.txt"));
    for (std::string line; std::getline(lines, line);) {
        std::istringstream words(line);
        std::vector<std::string> row;
        for (std::string word; words >> word;)
            row.push_back(word);
        output.rows.push_back(row);
    }
    return output;
}

// The device's `via EGL device N` of `render --stats`.
std::string renderedDevice(const std::filesystem::path& dir, const std::string& device)
{
    const test::ProcessResult result = runExecutable({"render", "-o", (dir / "out.png").string(), "--size", "32x18",
                                                      "--device", device, "--stats", (dir / "stats.json").string()});
    EXPECT_EQ(result.exitCode, 0) << result.stderrText;
    // Silent on the device platform: the fallback note is for the surfaceless platform only.
    EXPECT_EQ(result.stderrText, "");
    std::ifstream in(dir / "stats.json");
    return nlohmann::json::parse(in)["device"].get<std::string>();
}

TEST(DevicesCli, ListsEachDeviceWithItsUuidOrADash)
{
    const DevicesOutput output = runDevices(scratchDirectory());
    const EglPlatformChoice choice = eglPlatformChoice();
    if (!choice.canEnumerateDevices) {
        EXPECT_EQ(output.exitCode, 1);
        EXPECT_EQ(test::lineCount(output.stderrText), 1) << output.stderrText;
        EXPECT_NE(output.stderrText.find(choice.reason), std::string::npos) << output.stderrText;
        return;
    }
    ASSERT_EQ(output.exitCode, 0) << output.stderrText;
    EXPECT_EQ(output.stderrText, "");
    ASSERT_GE(output.rows.size(), 2u);
    EXPECT_EQ(output.rows[0].front(), "index");
    EXPECT_EQ(output.rows[0].back(), "uuid");
    for (std::size_t i = 1; i < output.rows.size(); ++i) {
        EXPECT_EQ(output.rows[i].front(), std::to_string(i - 1));
        const std::string& uuid = output.rows[i].back();
        DeviceSelector selector;
        if (uuid != "-") {
            EXPECT_EQ(parseDeviceSelector(uuid, selector), "") << uuid;
            EXPECT_EQ(formatDeviceSelector(selector), uuid);
        }
    }
}

TEST(DevicesCli, RendersOnTheDeviceOfAnIndex)
{
    if (!eglPlatformChoice().canEnumerateDevices)
        GTEST_SKIP() << "EGL cannot enumerate devices here: " << eglPlatformChoice().reason;
    const std::string device = renderedDevice(scratchDirectory(), "0");
    EXPECT_NE(device.find("via EGL device 0"), std::string::npos) << device;
}

TEST(DevicesCli, RendersOnTheDeviceOfAUuidInNvidiaSmisForm)
{
    const auto dir = scratchDirectory();
    const DevicesOutput output = runDevices(dir);
    for (std::size_t i = 1; i < output.rows.size(); ++i) {
        const std::vector<std::string>& row = output.rows[i];
        // A device that made a context: its renderer is not "(why none could be)".
        if (row.back() == "-" || row[2].front() == '(')
            continue;
        std::string upper = row.back();
        std::transform(upper.begin(), upper.end(), upper.begin(), [](unsigned char c) { return std::toupper(c); });
        const std::string device = renderedDevice(dir, "GPU-" + upper);
        EXPECT_NE(device.find("via EGL device " + row.front()), std::string::npos) << device;
        return;
    }
    GTEST_SKIP() << "no EGL device here makes a context and has EGL_EXT_device_persistent_id";
}

TEST(DevicesCli, AUuidThatNoDeviceHasIsOneLineAndExitOne)
{
    const auto dir = scratchDirectory();
    const test::ProcessResult result = runExecutable({"render", "-o", (dir / "out.png").string(), "--size", "32x18",
                                                      "--device", "GPU-EEEEEEEE-EEEE-EEEE-EEEE-EEEEEEEEEEEE"});
    EXPECT_EQ(result.exitCode, 1) << result.stderrText;
    EXPECT_EQ(test::lineCount(result.stderrText), 1) << result.stderrText;
    const std::string expected = eglPlatformChoice().canEnumerateDevices
                                     ? "manylights: --device eeeeeeee-eeee-eeee-eeee-eeeeeeeeeeee: no EGL device has "
                                       "this UUID"
                                     : "manylights: --device eeeeeeee-eeee-eeee-eeee-eeeeeeeeeeee: EGL cannot "
                                       "enumerate devices";
    EXPECT_EQ(result.stderrText.rfind(expected, 0), 0u) << result.stderrText;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
}

TEST(DevicesCli, AnIndexThatNoDeviceHasIsOneLineAndExitOne)
{
    const auto dir = scratchDirectory();
    const test::ProcessResult result =
        runExecutable({"render", "-o", (dir / "out.png").string(), "--size", "32x18", "--device", "999"});
    EXPECT_EQ(result.exitCode, 1) << result.stderrText;
    EXPECT_EQ(test::lineCount(result.stderrText), 1) << result.stderrText;
    EXPECT_EQ(result.stderrText.rfind("manylights: --device 999: ", 0), 0u) << result.stderrText;
}

TEST(DevicesCli, NeitherAnIndexNorAUuidIsAUsageError)
{
    for (const char* value : {"-1", "GPU-1234", "garbage", "3f2a0c4e9b1d4e7a8c550123456789ab"}) {
        const auto dir = scratchDirectory();
        const test::ProcessResult result =
            runExecutable({"render", "-o", (dir / "out.png").string(), "--size", "32x18", "--device", value});
        EXPECT_EQ(result.exitCode, 2) << value << ": " << result.stderrText;
        EXPECT_NE(result.stderrText.find("--device: must be a device's index"), std::string::npos) << result.stderrText;
        EXPECT_NE(result.stderrText.find(value), std::string::npos) << result.stderrText;
    }
}

}  // namespace
}  // namespace manylights
