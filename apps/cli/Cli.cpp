#include "apps/cli/Cli.h"

#include <cstdio>
#include <new>
#include <string>

#include <CLI/CLI.hpp>

#include "apps/cli/BenchCommand.h"
#include "apps/cli/CommandSupport.h"
#include "apps/cli/RenderCommand.h"
#include "render/Technique.h"
#include "core/Error.h"

namespace manylights {

int runCli(int argc, const char* const* argv)
{
    CLI::App app{"manylights: many-light deferred rendering techniques, side by side", "manylights"};
    app.require_subcommand(1);

    RenderOptions render;
    std::string size = "1280x720";
    std::string view = "final";
    std::string gbufferLayout(gbufferLayoutName(kDefaultGBufferLayout));
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
    CLI::Option* timeOption =
        renderCommand->add_option("--time", render.time, "Scene time in seconds")->check(CLI::NonNegativeNumber);
    std::string timeRange;
    CLI::Option* timeRangeOption =
        renderCommand
            ->add_option("--time-range", timeRange,
                         "Record frames from START to END seconds (START:END, END excluded); -o is then a "
                         "pattern such as frames/%04d.png")
            ->excludes(timeOption);
    CLI::Option* fpsOption =
        renderCommand->add_option("--fps", render.fps, "Frames per second of a --time-range recording")
            ->check(CLI::Range(0.001, 1000.0))
            ->capture_default_str();
    renderCommand->add_option("--lights", render.lights, "Replace the total count of the scene's light sets")
        ->check(CLI::Range(0, 16777216));
    renderCommand->add_option("--frames", render.frames, "Frames to render and time (after one warm-up frame)")
        ->check(CLI::Range(1, 100000));
    renderCommand->add_option("--stats", render.statsPath, "Write timings and work counts as JSON");
    renderCommand->add_option("--gbuffer", gbufferLayout, "G-buffer layout of the deferred techniques")
        ->check(CLI::IsMember({"seed", "compact"}))
        ->capture_default_str();
    addAnisotropyOption(*renderCommand, render.anisotropy);
    renderCommand
        ->add_option("--shadow-lights", render.shadowLights,
                     "Local lights that cast shadows (chosen by screen coverage x intensity)")
        ->check(CLI::Range(0, kMaxShadowLights))
        ->capture_default_str();
    renderCommand->add_flag("--rebuild-shadows", render.rebuildShadows,
                            "Render every shadow map every frame instead of reusing unchanged ones (to time them)");
    renderCommand->add_flag("--count-work", render.countWork,
                            "Count light evaluations and in-range pairs (into --stats; slows the frame)");

    BenchOptions bench;
    CLI::App* benchCommand = addBenchCommand(app, bench);

    if (const std::optional<int> status = parseCommandLine(app, argc, argv))
        return *status;

    if (benchCommand->parsed())
        return reportingErrors([&] { runBench(bench); }, "benchmarking");

    ImageSize renderSize;
    if (std::string problem = parseSize(size, renderSize); !problem.empty()) {
        std::fprintf(stderr, "manylights: %s\n", problem.c_str());
        return kExitUsage;
    }
    render.width = renderSize.width;
    render.height = renderSize.height;
    if (fpsOption->count() > 0 && timeRangeOption->count() == 0) {
        std::fprintf(stderr, "manylights: --fps applies only to a --time-range recording\n");
        return kExitUsage;
    }
    if (timeRangeOption->count() > 0) {
        TimeRange range;
        std::string problem = parseTimeRange(timeRange, range);
        if (problem.empty())
            problem = checkFramePattern(render.output);
        if (problem.empty() && !render.statsPath.empty())
            problem = "--stats measures one image; it does not combine with --time-range";
        if (!problem.empty()) {
            std::fprintf(stderr, "manylights: %s\n", problem.c_str());
            return kExitUsage;
        }
        render.timeRange = range;
    }
    const bool pfm = render.output.size() > 4 && render.output.ends_with(".pfm");
    const bool png = render.output.size() > 4 && render.output.ends_with(".png");
    if (!pfm && !png) {
        std::fprintf(stderr, "manylights: the output must end in .png or .pfm, got '%s'\n", render.output.c_str());
        return kExitUsage;
    }
    render.view = *parseViewMode(view);
    render.gbufferLayout = *parseGBufferLayout(gbufferLayout);

    return reportingErrors([&] { runRender(render); },
                           "rendering " + std::to_string(render.width) + "x" + std::to_string(render.height));
}

}  // namespace manylights
