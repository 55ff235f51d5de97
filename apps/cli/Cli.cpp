#include "apps/cli/Cli.h"

#include <cstdio>
#include <new>
#include <regex>

#include <CLI/CLI.hpp>

#include "apps/cli/RenderCommand.h"
#include "render/Technique.h"
#include "core/Error.h"

namespace manylights {

namespace {

constexpr int kExitFailure = 1;
constexpr int kExitUsage = 2;
// Far beyond any display, and small enough that width · height · bytes per pixel stays
// within 64-bit sizes; the GL implementation's own limit is checked when rendering.
constexpr int kMaxImageDimension = 32768;

// "WxH" with both in 1..kMaxImageDimension.
std::string parseSize(const std::string& text, int& width, int& height)
{
    static const std::regex pattern(R"((\d{1,6})x(\d{1,6}))");
    std::smatch match;
    if (!std::regex_match(text, match, pattern))
        return "--size must look like 1280x720, got '" + text + "'";
    width = std::stoi(match[1]);
    height = std::stoi(match[2]);
    if (width < 1 || height < 1 || width > kMaxImageDimension || height > kMaxImageDimension)
        return "--size must be between 1x1 and " + std::to_string(kMaxImageDimension) + "x" +
               std::to_string(kMaxImageDimension) + ", got " + text;
    return {};
}

}  // namespace

int runCli(int argc, const char* const* argv)
{
    CLI::App app{"manylights: many-light deferred rendering techniques, side by side", "manylights"};
    app.require_subcommand(1);

    RenderOptions render;
    std::string size = "1280x720";
    std::string view = "final";
    CLI::App* renderCommand = app.add_subcommand("render", "Render a scene to an image");
    renderCommand->add_option("scene", render.scenePath, "Scene file (JSON); the built-in default scene if absent");
    renderCommand->add_option("-o,--output", render.output, "Output image: .png or .pfm")->required();
    renderCommand->add_option("--size", size, "Image size WxH")->capture_default_str();
    renderCommand->add_option("--technique", render.technique, "Lighting technique")
        ->check(CLI::IsMember(techniqueNames()))
        ->capture_default_str();
    renderCommand->add_option("--view", view, "What to show")
        ->check(CLI::IsMember(viewModeNames()))
        ->capture_default_str();
    renderCommand->add_option("--time", render.time, "Scene time in seconds")->check(CLI::NonNegativeNumber);
    renderCommand->add_option("--lights", render.lights, "Replace the total count of the scene's light sets")
        ->check(CLI::Range(0, 16777216));
    renderCommand->add_option("--frames", render.frames, "Frames to render and time (after one warm-up frame)")
        ->check(CLI::Range(1, 100000));
    renderCommand->add_option("--stats", render.statsPath, "Write timings and work counts as JSON");
    renderCommand->add_flag("--count-work", render.countWork,
                            "Count light evaluations and in-range pairs (into --stats; slows the frame)");

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& help) {
        return app.exit(help);
    } catch (const CLI::ParseError& error) {
        app.exit(error);
        return kExitUsage;
    }

    if (std::string problem = parseSize(size, render.width, render.height); !problem.empty()) {
        std::fprintf(stderr, "manylights: %s\n", problem.c_str());
        return kExitUsage;
    }
    const bool pfm = render.output.size() > 4 && render.output.ends_with(".pfm");
    const bool png = render.output.size() > 4 && render.output.ends_with(".png");
    if (!pfm && !png) {
        std::fprintf(stderr, "manylights: the output must end in .png or .pfm, got '%s'\n", render.output.c_str());
        return kExitUsage;
    }
    render.view = *parseViewMode(view);

    try {
        runRender(render);
    } catch (const Error& error) {
        std::fprintf(stderr, "manylights: %s\n", error.what());
        return kExitFailure;
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "manylights: out of memory rendering %dx%d\n", render.width, render.height);
        return kExitFailure;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "manylights: %s\n", error.what());
        return kExitFailure;
    }
    return 0;
}

}  // namespace manylights
