#include "apps/cli/Cli.h"

#include <cstdio>
#include <filesystem>
#include <iterator>
#include <new>
#include <string>
#include <utility>

#include <CLI/CLI.hpp>

#include "apps/cli/BenchCommand.h"
#include "apps/cli/CommandSupport.h"
#include "apps/cli/DevicesCommand.h"
#include "apps/cli/OutputOptions.h"
#include "apps/cli/RenderCommand.h"
#include "core/Error.h"
#include "core/Numbers.h"
#include "render/output/Image.h"
#include "render/techniques/Technique.h"

namespace manylights {

int runCli(int argc, const char* const* argv)
{
    CLI::App app{"manylights: many-light deferred rendering techniques, side by side", "manylights"};
    app.require_subcommand(1);
    app.set_version_flag("--version", std::string("manylights ") + MANYLIGHTS_VERSION);
    // main.cpp hands `manylights view ...` to the viewer before this parser runs; the entry is
    // here so that --help lists every command.
    app.add_subcommand("view", "Show the scene in a window, interactively (manylights view --help)");

    RenderOptions render;
    std::string view = "final";
    CLI::App* renderCommand = app.add_subcommand("render", "Render a scene to an image");
    renderCommand->add_option("scene", render.scenePath, "Scene file (JSON); the built-in default scene if absent");
    renderCommand->add_option("-o,--output", render.output.path, "Output image: .png, .pfm or .exr")->required();
    addSizeOption(*renderCommand, render.size, "Image size WxH");
    addTechniqueOption(*renderCommand, render.technique);
    renderCommand->add_option("--view", view, "What to show")
        ->check(CLI::IsMember(viewModeNames()))
        ->capture_default_str();
    CLI::Option* timeOption = renderCommand->add_option("--time", render.time, "Scene time in seconds")
                                  ->check(numberIn(0.0, kMaxSceneSeconds));
    std::string timeRange;
    CLI::Option* timeRangeOption =
        renderCommand
            ->add_option("--time-range", timeRange,
                         "Record frames from START to END seconds (START:END, END excluded); -o is then a "
                         "pattern such as frames/%04d.png")
            ->excludes(timeOption);
    CLI::Option* fpsOption =
        renderCommand->add_option("--fps", render.fps, "Frames per second of a --time-range recording")
            ->check(numberIn(0.001, 1000.0))
            ->capture_default_str();
    std::string shard;
    CLI::Option* shardOption = renderCommand->add_option(
        "--shard", shard, "Render only the frames k with k mod N = I-1 of a --time-range recording (I/N)");
    renderCommand->add_flag("--skip-existing", render.skipExisting,
                            "Render only the frames of a --time-range recording whose files are missing");
    addLightCountOption(*renderCommand, render.lights);
    renderCommand->add_option("--frames", render.frames, "Frames to render and time (after one warm-up frame)")
        ->check(CLI::Range(1, 100000));
    renderCommand->add_option("--stats", render.statsPath, "Write timings and work counts as JSON");
    addGBufferOption(*renderCommand, render.gbufferLayout);
    addAnisotropyOption(*renderCommand, render.anisotropy);
    addDriverOptions(*renderCommand, render.driver);
    addShadowOptions(*renderCommand, render.shadows);
    addRebuildShadowsOption(*renderCommand, render.rebuildShadows);
    addCameraOptions(*renderCommand, render.camera);
    renderCommand->add_flag("--strict", render.strict, "Treat what model files get forgiven (warnings) as errors");
    addDisplayOptions(*renderCommand, render.display);
    renderCommand
        ->add_option("--supersample", render.supersample,
                     "Render N x N pixels per output pixel and box-filter them down in linear light")
        ->check(CLI::Range(1, kMaxSupersample))
        ->capture_default_str();
    renderCommand->add_flag("--exr-float", render.exrFloat, "Write EXR channels as 32-bit floats instead of half");
    renderCommand->add_flag("--aovs", render.aovs,
                            "Add the G-buffer quantities (position, normal, ..., ssao) as layers of the EXR output");
    bool noLegend = false;
    renderCommand->add_flag(
        "--no-legend", noLegend,
        "Leave the labelled colour bar out of a light-count or shadow-resolution view's PNG (for analysis)");
    renderCommand->add_flag("--count-work", render.countWork,
                            "Count light evaluations and in-range pairs (into --stats; slows the frame)");

    BenchOptions bench;
    CLI::App* benchCommand = addBenchCommand(app, bench);
    CLI::App* devicesCommand = app.add_subcommand(
        "devices",
        "List the EGL devices: index (for --device), vendor, renderer, software or not, UUID (for --device too)");

    if (const std::optional<int> status = parseCommandLine(app, argc, argv))
        return *status;
    const auto usageError = [](const std::string& problem) {
        std::fprintf(stderr, "manylights: %s\n", printableLine(problem).c_str());
        return kExitUsage;
    };

    if (devicesCommand->parsed())
        return reportingErrors([] { printDevices(); }, "listing the EGL devices");
    if (benchCommand->parsed()) {
        const std::pair<const char*, const std::string*> outputs[] = {
            {"--csv", &bench.csvPath}, {"--plot", &bench.plotPath}, {"--json", &bench.jsonPath}};
        for (std::size_t i = 0; i < std::size(outputs); ++i)
            for (std::size_t j = i + 1; j < std::size(outputs); ++j)
                if (!outputs[i].second->empty() && !outputs[j].second->empty() &&
                    sameFile(*outputs[i].second, *outputs[j].second))
                    return usageError(std::string(outputs[i].first) + " and " + outputs[j].first +
                                      " name the same file '" + *outputs[i].second + "'");
        // A budget skips a technique's later cases from its earlier ones, which another shard
        // may time; a plot of one shard's cases is a fraction of the sweep.
        if (!bench.shard.isWhole() && (bench.budgetMs > 0.0 || !bench.plotPath.empty()))
            return usageError("--shard does not combine with --budget-ms or --plot, which need the whole sweep");
        return reportingErrors([&] { runBench(bench); }, "benchmarking");
    }

    if (fpsOption->count() > 0 && timeRangeOption->count() == 0)
        return usageError("--fps applies only to a --time-range recording");
    if (timeRangeOption->count() == 0 && (shardOption->count() > 0 || render.skipExisting))
        return usageError("--shard and --skip-existing apply only to a --time-range recording");
    if (shardOption->count() > 0)
        if (std::string problem = parseShard(shard, render.shard); !problem.empty())
            return usageError(problem);
    if (timeRangeOption->count() > 0) {
        TimeRange range;
        std::string problem = parseTimeRange(timeRange, range);
        if (problem.empty())
            problem = checkFramePattern(render.output.path);
        if (problem.empty())
            problem = checkRecordingFrameCount(range, render.fps);
        if (problem.empty() && !render.statsPath.empty())
            problem = "--stats measures one image; it does not combine with --time-range";
        if (!problem.empty())
            return usageError(problem);
        render.timeRange = range;
    }
    const std::optional<ImageFormat> format = imageFormatOf(render.output.path);
    if (!format)
        return usageError("the output must end in .png, .pfm or .exr, got '" + render.output.path + "'");
    render.output.format = *format;
    const std::string problem = outputOptionProblem(
        [renderCommand](std::string_view option) { return renderCommand->count(std::string(option)) > 0; },
        render.output.format);
    if (!problem.empty())
        return usageError(problem);
    if (!render.statsPath.empty() && sameFile(render.output.path, render.statsPath))
        return usageError("--stats and -o name the same file '" + render.output.path + "'");
    render.view = *parseViewMode(view);
    if (render.supersample > 1 && !showsFinalImage(render.view))
        return usageError("--supersample applies to the final, volumes and volume-corners views, not '" + view + "'");
    if (render.aovs && render.view != ViewMode::Final)
        return usageError("--aovs adds the G-buffer views to the final image; it does not combine with --view " + view);
    if (noLegend && !hasLegend(render.view))
        return usageError("--no-legend applies to --view light-count and shadow-resolution, not '" + view + "'");
    render.legend = !noLegend;

    return reportingErrors([&] { runRender(render); }, "rendering " + formatSize(render.size));
}

}  // namespace manylights
