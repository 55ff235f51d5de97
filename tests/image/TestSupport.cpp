#include "TestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>
#include <sys/wait.h>

#include "apps/cli/Cli.h"

namespace manylights::test {

std::string testDriverProfile()
{
    const char* profile = std::getenv("MANYLIGHTS_TEST_DRIVER_PROFILE");
    return profile ? profile : "";
}

std::vector<std::string> withTestDriverProfile(std::vector<std::string> args)
{
    const std::string profile = testDriverProfile();
    const bool command = !args.empty() && (args.front() == "render" || args.front() == "bench");
    if (!profile.empty() && command && std::find(args.begin(), args.end(), "--driver-profile") == args.end())
        args.insert(args.end(), {"--driver-profile", profile});
    return args;
}

std::filesystem::path scratchDirectory()
{
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    // Parameterised suites and tests have '/' in their names: one flat folder per test.
    const std::string profile = testDriverProfile();
    std::string name = (profile.empty() ? "" : profile + ".") + info->test_suite_name() + "." + info->name();
    std::replace(name.begin(), name.end(), '/', '_');
    const std::filesystem::path directory = std::filesystem::current_path() / "test-output" / name;
    std::filesystem::remove_all(directory);
    std::filesystem::create_directories(directory);
    return directory;
}

void writeFile(const std::filesystem::path& path, const std::string& text)
{
    std::ofstream out(path, std::ios::binary);
    out << text;
    ASSERT_TRUE(out.good()) << path;
}

std::string readFile(const std::filesystem::path& path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

int lineCount(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

void runCliOrFail(const std::vector<std::string>& commandLine)
{
    const std::vector<std::string> args = withTestDriverProfile(commandLine);
    std::vector<const char*> argv = {"manylights"};
    for (const std::string& arg : args)
        argv.push_back(arg.c_str());
    const int status = runCli(static_cast<int>(argv.size()), argv.data());
    ASSERT_EQ(status, 0) << "manylights failed";
}

Image renderPfm(const std::string& scene, const std::filesystem::path& output,
                const std::vector<std::string>& extraArgs)
{
    std::vector<std::string> args = {"render"};
    if (!scene.empty())
        args.push_back(scene);
    args.insert(args.end(), {"-o", output.string()});
    args.insert(args.end(), extraArgs.begin(), extraArgs.end());
    runCliOrFail(args);
    if (::testing::Test::HasFatalFailure())
        return {};
    return readPfm(output);
}

ProcessResult runExecutable(const std::vector<std::string>& args, const std::string& environment)
{
    const std::string pid = std::to_string(::getpid());
    const std::filesystem::path errors = std::filesystem::temp_directory_path() / ("manylights-stderr-" + pid + ".txt");
    const std::filesystem::path output = std::filesystem::temp_directory_path() / ("manylights-stdout-" + pid + ".txt");
    std::string command = environment + " '" MANYLIGHTS_EXE "'";
    for (const std::string& arg : withTestDriverProfile(args))
        command += " '" + arg + "'";
    command += " >'" + output.string() + "' 2>'" + errors.string() + "' </dev/null";
    const int status = std::system(command.c_str());
    ProcessResult result;
    result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    const auto take = [](const std::filesystem::path& path) {
        std::stringstream text;
        text << std::ifstream(path).rdbuf();
        std::filesystem::remove(path);
        return text.str();
    };
    result.stderrText = take(errors);
    result.stdoutText = take(output);
    return result;
}

}  // namespace manylights::test
