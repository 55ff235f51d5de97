#include "apps/cli/CommandSupport.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <regex>

#include <CLI/CLI.hpp>

#include "core/AtomicFile.h"
#include "core/Error.h"
#include "core/Numbers.h"
#include "render/TextureCache.h"
#include "scene/DefaultScene.h"
#include "scene/SceneLoader.h"

namespace manylights {

std::string parseSize(const std::string& text, ImageSize& size)
{
    // At most 6 digits each, so std::stoi cannot overflow before the range check.
    static const std::regex pattern(R"((\d{1,6})x(\d{1,6}))");
    std::smatch match;
    if (!std::regex_match(text, match, pattern))
        return "--size must look like 1280x720, got '" + text + "'";
    const int width = std::stoi(match[1]);
    const int height = std::stoi(match[2]);
    if (width < 1 || height < 1 || width > kMaxImageDimension || height > kMaxImageDimension)
        return "--size must be between 1x1 and " + std::to_string(kMaxImageDimension) + "x" +
               std::to_string(kMaxImageDimension) + ", got " + text;
    size = {width, height};
    return {};
}

void addAnisotropyOption(CLI::App& command, int& level)
{
    command
        .add_option_function<std::string>(
            "--anisotropy",
            [&level](const std::string& choice) { level = choice == "auto" ? kAutoAnisotropy : std::stoi(choice); },
            "Anisotropic filtering of material textures (auto: none on a software rasteriser, 8 on a GPU)")
        ->check(CLI::IsMember({"auto", "1", "2", "4", "8", "16"}))
        ->default_str("auto");
}

std::string formatSize(const ImageSize& size)
{
    return std::to_string(size.width) + "x" + std::to_string(size.height);
}

Statistics summarize(std::vector<double> values)
{
    ML_ASSERT(!values.empty());
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    const double median = n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
    return {median, values.front(), values.back()};
}

CLI::Validator numberIn(double min, double max)
{
    return CLI::Validator(
        [min, max](const std::string& text) {
            double value = 0.0;
            return checkNumber(text, min, max, value);
        },
        "NUMBER");
}

Scene loadSceneForCommand(const std::string& path, bool strict)
{
    Scene scene = path.empty() ? makeDefaultScene() : loadSceneFile(path, {.strict = strict});
    for (const std::string& warning : scene.warnings)
        std::fprintf(stderr, "manylights: warning: %s\n", printableLine(warning).c_str());
    return scene;
}

bool sameFile(const std::string& a, const std::string& b)
{
    std::error_code error;
    const auto resolved = [&](const std::string& path) {
        return std::filesystem::weakly_canonical(std::filesystem::absolute(path, error), error);
    };
    return resolved(a) == resolved(b);
}

bool endsWith(const std::string& text, const std::string& suffix)
{
    return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::optional<int> parseCommandLine(CLI::App& app, int argc, const char* const* argv)
{
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& help) {
        return app.exit(help);
    } catch (const CLI::ParseError& error) {
        // --version ends the parse too, successfully (exit code 0).
        return app.exit(error) == 0 ? 0 : kExitUsage;
    }
    return std::nullopt;
}

}  // namespace manylights
