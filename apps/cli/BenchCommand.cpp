#include "apps/cli/BenchCommand.h"

#include <algorithm>
#include <chrono>
#include <cinttypes>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <type_traits>

#include <epoxy/gl.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "apps/cli/Progress.h"
#include "apps/cli/SvgPlot.h"
#include "core/AtomicFile.h"
#include "core/Error.h"
#include "platform/HeadlessContext.h"
#include "render/Renderer.h"
#include "render/Techniques.h"
#include "render/output/Image.h"
#include "scene/LightSets.h"

namespace manylights {

namespace {

// Within what `render --lights` and `--frames` accept.
constexpr int kMaxFrames = 100'000;

// One combination of the sweep.
struct BenchResult {
    std::string technique;
    std::size_t lights = 0;  // every light rendered: the scene's explicit lights and its sets'
    ImageSize size;
    int frames = 0;
    FrameSummary measured;           // the measured frames
    int warmupFrames = 0;            // rendered before them
    std::optional<WorkCounts> work;  // with --count-work
    // For --json: the stage the technique lit in, and its counters after the timed frames (after
    // the counting frame with --count-work).
    std::string lightingStage;
    std::vector<TechniqueCounter> counters;
};

// --warmup auto: the warm-up ends once kSettledFrames frames in a row (the first frame, which
// compiles and allocates, never among them) lie within kSettledSpread of each other, or after
// kWarmupTimeBox and at least two frames, or after kMaxWarmupFrames.
constexpr int kSettledFrames = 3;
constexpr double kSettledSpread = 1.10;  // the slowest of them at most 10% over the fastest
constexpr std::chrono::milliseconds kWarmupTimeBox{1000};
constexpr int kMaxWarmupFrames = 100;

bool settled(const std::vector<FrameSample>& frames)
{
    if (frames.size() < 1 + kSettledFrames)
        return false;
    const auto last = frames.end() - kSettledFrames;
    const auto [fastest, slowest] = std::minmax_element(
        last, frames.end(), [](const FrameSample& a, const FrameSample& b) { return a.wallMs < b.wallMs; });
    return slowest->wallMs <= kSettledSpread * fastest->wallMs;
}

// Rejects a list that names an entry twice: the sweep would measure it twice and the plot
// would draw a line back on itself, so a repeat is almost surely a typo.
template <typename T>
void rejectRepeats(const std::vector<T>& values, const std::string& option)
{
    std::set<T> seen;
    for (const T& value : values)
        if (!seen.insert(value).second) {
            if constexpr (std::is_same_v<T, std::string>)
                throw CLI::ValidationError(option, "lists " + value + " twice");
            else
                throw CLI::ValidationError(option, "lists " + std::to_string(value) + " twice");
        }
}

std::optional<std::uint64_t> totalFragmentInvocations(const std::vector<PassSummary>& passes)
{
    std::uint64_t total = 0;
    for (const PassSummary& pass : passes) {
        if (!pass.fragmentInvocations)
            return std::nullopt;
        total += *pass.fragmentInvocations;
    }
    return total;
}

BenchResult measure(const Scene& scene, const std::vector<Light>& lights, const std::string& techniqueName,
                    ImageSize size, const BenchOptions& options, const CullingTuning& culling)
{
    RendererDesc desc{.width = size.width,
                      .height = size.height,
                      .gbufferLayout = options.gbufferLayout,
                      .shadowLights = chooseShadowLights(scene, options.shadows),
                      .shadowPoolMiB = options.shadows.poolMiB,
                      .rebuildShadowsEveryFrame = options.rebuildShadows,
                      .anisotropy = options.anisotropy,
                      .display = chooseDisplay(scene, options.display),
                      .driver = options.driver.overrides,
                      .culling = culling};
    Renderer renderer(scene, lights, desc);
    printWarnings(renderer.gpuScene().environment().warnings());
    Technique& technique = renderer.technique(techniqueName);
    // Under PassTiming::Wall each frame is rendered and waited for; otherwise frames are issued
    // back to back, as an application issues them, and their samples arrive a frame or two
    // later. Either way `finished` holds the samples of the frames kept, in the order issued:
    // a frame whose lists overflowed their storage (ClusterLists) is dropped, and another is
    // issued in its place (the technique counts it in cluster_rebuilds).
    const bool backToBack = renderer.passTiming() != PassTiming::Wall;
    std::vector<FrameSample> finished;
    int frameNumber = 0;
    const auto renderNextFrame = [&] {
        ++frameNumber;
        const auto start = std::chrono::steady_clock::now();
        if (options.fps)
            renderer.setTime(frameNumber / *options.fps);
        const std::chrono::duration<double, std::milli> posing = std::chrono::steady_clock::now() - start;
        if (!backToBack) {
            // The frame's wall time from glFinish to glFinish, plus the posing before it: what a
            // recording or the viewer pays per frame of an animation. (Back to back, the period
            // from frame to frame includes the posing already.)
            FrameSample sample = renderer.renderFrame(technique, ViewMode::Final);
            sample.wallMs += posing.count();
            finished.push_back(std::move(sample));
            return;
        }
        renderer.queueFrame(technique, ViewMode::Final);
        for (Renderer::FinishedFrame& frame : renderer.finishedFrames(false))
            if (frame.fitted)
                finished.push_back(std::move(frame.sample));
    };
    std::size_t warmup = 0;
    if (options.warmup) {
        warmup = static_cast<std::size_t>(*options.warmup);
        while (finished.size() < warmup)
            renderNextFrame();
    } else {
        const auto start = std::chrono::steady_clock::now();
        while (true) {
            renderNextFrame();
            if (settled(finished) || frameNumber >= kMaxWarmupFrames ||
                (finished.size() >= 2 && std::chrono::steady_clock::now() - start >= kWarmupTimeBox))
                break;
        }
        warmup = finished.size();
    }
    while (finished.size() < warmup + static_cast<std::size_t>(options.frames))
        renderNextFrame();
    // The frames still in flight finish; the window is the frames after the warm-up.
    renderer.finishedFrames(true);
    const std::vector<FrameSample> frames(finished.begin() + static_cast<std::ptrdiff_t>(warmup),
                                          finished.begin() + static_cast<std::ptrdiff_t>(warmup) + options.frames);

    BenchResult result;
    result.technique = techniqueName;
    result.lights = lights.size();
    result.size = size;
    result.frames = options.frames;
    result.measured = summarizeFrames(frames);
    result.warmupFrames = static_cast<int>(warmup);
    result.lightingStage = lightingStageName(technique.options().lightingStage);
    result.counters = technique.counters();
    for (const TechniqueCounter& counter : renderer.shadowPool().counters())
        result.counters.push_back(counter);

    if (options.countWork) {
        // A separate frame with the counting variant: its atomics would distort the timings.
        desc.countWork = true;
        renderer.apply(desc);
        renderer.renderFrame(techniqueName, ViewMode::Final);
        result.work = renderer.lastWorkCounts();
        // The counters the counting frame adds (cluster_list_visits) with the others of that frame.
        result.counters = renderer.technique(techniqueName).counters();
    }
    return result;
}

// "[3/12] deferred 4096 lights 1280x720": the sweep's case number before its label.
std::string caseLabel(std::size_t index, std::size_t total, const std::string& label)
{
    // Appended piece by piece: GCC 12's -Wrestrict misreads the chain of + inlined here.
    std::string text = "[";
    text += std::to_string(index);
    text += '/';
    text += std::to_string(total);
    text += "] ";
    text += label;
    return text;
}

std::string formatMs(double ms)
{
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.3f", ms);
    return buffer;
}

// RFC 4180: a field with a comma, quote or line break is quoted, its quotes doubled.
std::string csvField(const std::string& text)
{
    if (text.find_first_of(",\"\r\n") == std::string::npos)
        return text;
    std::string quoted = "\"";
    for (const char c : text) {
        if (c == '"')
            quoted += '"';
        quoted += c;
    }
    return quoted + "\"";
}

std::string optionalCount(const std::optional<std::uint64_t>& count)
{
    return count ? std::to_string(*count) : std::string();
}

std::string optionalMs(const std::optional<double>& ms) { return ms ? formatMs(*ms) : std::string(); }

// docs/cli.md documents every column. Without the header line for the shards after the first.
std::string csvText(const std::vector<BenchResult>& results, bool header)
{
    std::string text =
        !header ? ""
                : "technique,lights,width,height,frames,frame_ms_median,frame_ms_min,frame_ms_max,frame_gpu_ms_median,"
                  "fragment_invocations,passes,light_evaluations,in_range_pairs,transparent_light_evaluations,"
                  "pass_timing,warmup_frames,frame_ms_p95,frame_gpu_ms_p95,pass_gpu_ms\n";
    for (const BenchResult& r : results) {
        std::string passes;
        std::string passGpuMs;
        for (const PassSummary& pass : r.measured.passes) {
            if (!passes.empty())
                passes += ';';
            passes += pass.name + ':' + optionalMs(pass.wallMs) + ':' + optionalCount(pass.fragmentInvocations);
            if (!passGpuMs.empty())
                passGpuMs += ';';
            passGpuMs += pass.name + ':' + optionalMs(pass.gpuMs);
        }
        const std::vector<std::string> fields = {
            r.technique,
            std::to_string(r.lights),
            std::to_string(r.size.width),
            std::to_string(r.size.height),
            std::to_string(r.frames),
            formatMs(r.measured.wallMs.median),
            formatMs(r.measured.wallMs.min),
            formatMs(r.measured.wallMs.max),
            formatMs(r.measured.gpuMs.median),
            optionalCount(totalFragmentInvocations(r.measured.passes)),
            passes,
            r.work ? std::to_string(r.work->lightEvaluations) : "",
            r.work ? std::to_string(r.work->inRangePairs) : "",
            r.work ? std::to_string(r.work->transparentLightEvaluations) : "",
            std::string(passTimingName(r.measured.timing)),
            std::to_string(r.warmupFrames),
            formatMs(r.measured.wallMs.p95),
            formatMs(r.measured.gpuMs.p95),
            passGpuMs,
        };
        for (std::size_t i = 0; i < fields.size(); ++i) {
            if (i)
                text += ',';
            text += csvField(fields[i]);
        }
        text += '\n';
    }
    return text;
}

// --json (docs/cli.md, "JSON"): `header` (what ran the sweep, and on what) and one object per
// combination, each pass with its median time on the clock the frames were timed with, named,
// so that a script need not know which clock --pass-timing implies.
std::string jsonText(const std::vector<BenchResult>& results, nlohmann::json header)
{
    const auto optionalJson = [](const auto& value) {
        return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
    };
    const auto statisticsJson = [](const Statistics& statistics) {
        return nlohmann::json{
            {"median", statistics.median}, {"p95", statistics.p95}, {"min", statistics.min}, {"max", statistics.max}};
    };
    nlohmann::json combinations = nlohmann::json::array();
    for (const BenchResult& r : results) {
        nlohmann::json passes = nlohmann::json::array();
        for (const PassSummary& pass : r.measured.passes) {
            // Under Wall each pass is waited for; under Gpu its GL_TIME_ELAPSED; under Frame none.
            const std::optional<double> ms = r.measured.timing == PassTiming::Wall ? pass.wallMs : pass.gpuMs;
            const char* clock = !ms ? nullptr : r.measured.timing == PassTiming::Wall ? "wall" : "gpu";
            passes.push_back({{"name", pass.name},
                              {"ms", optionalJson(ms)},
                              {"clock", clock ? nlohmann::json(clock) : nlohmann::json(nullptr)},
                              {"wall_ms", optionalJson(pass.wallMs)},
                              {"gpu_ms", optionalJson(pass.gpuMs)},
                              {"fragment_invocations", optionalJson(pass.fragmentInvocations)}});
        }
        nlohmann::json counters = nlohmann::json::object();
        for (const TechniqueCounter& counter : r.counters)
            counters[counter.name] = counter.value;
        nlohmann::json combination = {{"technique", r.technique},
                                      {"lights", r.lights},
                                      {"width", r.size.width},
                                      {"height", r.size.height},
                                      {"frames", r.frames},
                                      {"warmup_frames", r.warmupFrames},
                                      {"pass_timing", std::string(passTimingName(r.measured.timing))},
                                      {"lighting_stage", r.lightingStage},
                                      {"frame_ms", statisticsJson(r.measured.wallMs)},
                                      {"frame_gpu_ms", statisticsJson(r.measured.gpuMs)},
                                      {"passes", passes},
                                      {"counters", counters}};
        if (r.work)
            combination["work"] = {{"light_evaluations", r.work->lightEvaluations},
                                   {"in_range_pairs", r.work->inRangePairs},
                                   {"transparent_light_evaluations", r.work->transparentLightEvaluations}};
        combinations.push_back(std::move(combination));
    }
    header["results"] = std::move(combinations);
    return header.dump(2) + "\n";
}

// Columns padded to their widest cell; text columns left-aligned, numbers right-aligned.
std::string formatTable(const std::vector<std::vector<std::string>>& rows, const std::vector<bool>& leftAligned)
{
    std::vector<std::size_t> widths(leftAligned.size(), 0);
    for (const auto& row : rows)
        for (std::size_t c = 0; c < row.size(); ++c)
            widths[c] = std::max(widths[c], row[c].size());
    std::string text;
    for (const auto& row : rows) {
        std::string line;
        for (std::size_t c = 0; c < row.size(); ++c) {
            const std::string padding(widths[c] - row[c].size(), ' ');
            if (c)
                line += "  ";
            line += leftAligned[c] ? row[c] + padding : padding + row[c];
        }
        while (!line.empty() && line.back() == ' ')
            line.pop_back();
        text += line + '\n';
    }
    return text;
}

std::string tableText(const std::vector<BenchResult>& results, bool countWork, PassTiming timing)
{
    std::vector<std::vector<std::string>> rows;
    std::vector<bool> left = {true, false, false, false, false, false, false, false};
    rows.push_back({"technique", "lights", "size", "median ms", "p95 ms", "min ms", "max ms", "gpu median ms"});
    if (countWork) {
        rows.back().insert(rows.back().end(), {"light evals", "in range", "efficiency"});
        left.insert(left.end(), {false, false, false});
    }
    // The pass times of the clock the frames were timed with (one sweep, one timing).
    rows.back().push_back(timing == PassTiming::Wall ? "passes (median wall ms)" : "passes (median gpu ms)");
    left.push_back(true);
    for (const BenchResult& r : results) {
        std::vector<std::string> row = {r.technique,
                                        std::to_string(r.lights),
                                        formatSize(r.size),
                                        formatMs(r.measured.wallMs.median),
                                        formatMs(r.measured.wallMs.p95),
                                        formatMs(r.measured.wallMs.min),
                                        formatMs(r.measured.wallMs.max),
                                        formatMs(r.measured.gpuMs.median)};
        if (countWork) {
            row.push_back(std::to_string(r.work->lightEvaluations));
            row.push_back(std::to_string(r.work->inRangePairs));
            // in_range_pairs / light_evaluations: 100% is perfect culling (docs/techniques.md).
            char efficiency[32] = "-";
            if (r.work->lightEvaluations > 0)
                std::snprintf(efficiency, sizeof efficiency, "%.1f%%",
                              100.0 * static_cast<double>(r.work->inRangePairs) /
                                  static_cast<double>(r.work->lightEvaluations));
            row.emplace_back(efficiency);
        }
        std::string passes;
        for (const PassSummary& pass : r.measured.passes) {
            const std::optional<double> ms = timing == PassTiming::Wall ? pass.wallMs : pass.gpuMs;
            char entry[96];
            if (ms)
                std::snprintf(entry, sizeof entry, "%s%s %.1f", passes.empty() ? "" : ", ", pass.name.c_str(), *ms);
            else
                std::snprintf(entry, sizeof entry, "%s%s -", passes.empty() ? "" : ", ", pass.name.c_str());
            passes += entry;
        }
        row.push_back(passes);
        rows.push_back(std::move(row));
    }
    return formatTable(rows, left);
}

// What the table's columns measure, by how the frames were timed (docs/cli.md, `bench`).
std::string clocksText(PassTiming timing, const std::string& warmup, int frames)
{
    char counts[64];
    std::snprintf(counts, sizeof counts, ", then %d timed frame%s. ", frames, frames == 1 ? "" : "s");
    std::string text = warmup;
    text += counts;
    switch (timing) {
    case PassTiming::Wall:
        text += "Pass timing wall: each frame and pass waited for (glFinish before and after); median/p95/min/max ms "
                "on the CPU clock, gpu median ms between GL_TIMESTAMP queries, passes on the CPU clock.";
        break;
    case PassTiming::Gpu:
        text += "Pass timing gpu: frames issued back to back (at most 2 in flight), nothing waited for; "
                "median/p95/min/max ms the CPU's period from frame to frame, gpu median ms between GL_TIMESTAMP "
                "queries, passes GL_TIME_ELAPSED.";
        break;
    case PassTiming::Frame:
        text += "Pass timing frame: as gpu, without the per-pass queries (the profiler's own cost left out).";
        break;
    }
    return text + "\n";
}

std::string plotText(const std::vector<BenchResult>& results, const BenchOptions& options,
                     const std::vector<std::string>& techniques, const std::string& sceneName)
{
    LogLogPlot plot;
    plot.xLabel = "lights";
    plot.yLabel = "frame time (ms, wall clock)";
    for (const ImageSize& size : options.sizes) {
        PlotPanel panel;
        panel.title = sceneName + ", " + formatSize(size) + ": ";
        panel.title += options.frames == 1
                           ? "one frame"
                           : "median of " + std::to_string(options.frames) + " frames, bars from min to max";
        for (const std::string& technique : techniques) {
            PlotSeries series;
            series.name = technique;
            // By the technique's place in the full list, so a technique keeps its colour in
            // every plot whatever subset a sweep runs.
            const auto& names = techniqueNames();
            series.colour = paletteColour(
                static_cast<std::size_t>(std::find(names.begin(), names.end(), technique) - names.begin()));
            for (const BenchResult& r : results) {
                if (r.technique != technique || r.size.width != size.width || r.size.height != size.height)
                    continue;
                char note[128];
                std::snprintf(note, sizeof note, "%s: %zu lights, %.1f ms (min %.1f, max %.1f)", technique.c_str(),
                              r.lights, r.measured.wallMs.median, r.measured.wallMs.min, r.measured.wallMs.max);
                series.points.push_back({static_cast<double>(r.lights), r.measured.wallMs.median, r.measured.wallMs.min,
                                         r.measured.wallMs.max, note});
            }
            panel.series.push_back(std::move(series));
        }
        plot.panels.push_back(std::move(panel));
    }
    return logLogSvg(plot);
}

}  // namespace

CLI::App* addBenchCommand(CLI::App& app, BenchOptions& options)
{
    CLI::App* bench = app.add_subcommand("bench", "Time techniques over light counts and image sizes");
    bench->add_option("scene", options.scenePath, "Scene file (JSON); the built-in default scene if absent");
    // The comma-separated lists take one argument each, so a scene given after them is not
    // read as one more entry.
    bench
        ->add_option_function<std::vector<std::string>>(
            "--techniques",
            [&options](const std::vector<std::string>& names) {
                rejectRepeats(names, "--techniques");
                options.techniques = names;
            },
            "Comma-separated techniques to time (default: all)")
        ->delimiter(',')
        ->allow_extra_args(false)
        ->check(CLI::IsMember(techniqueNames()));
    bench
        ->add_option_function<std::vector<int>>(
            "--lights",
            [&options](const std::vector<int>& counts) {
                rejectRepeats(counts, "--lights");
                options.lightCounts = counts;
            },
            "Comma-separated totals for the scene's light sets (default: the scene's own)")
        ->delimiter(',')
        ->allow_extra_args(false)
        ->check(CLI::Range(0, kMaxLightCount));
    bench
        ->add_option_function<std::vector<std::string>>(
            "--size",
            [&options](const std::vector<std::string>& texts) {
                rejectRepeats(texts, "--size");
                options.sizes.clear();
                for (const std::string& text : texts) {
                    ImageSize size;
                    parseSize(text, size);  // the check below has accepted it
                    options.sizes.push_back(size);
                }
            },
            "Comma-separated image sizes WxH (default: " + formatSize(kDefaultImageSize) + ")")
        ->delimiter(',')
        ->allow_extra_args(false)
        ->check(sizeValidator());
    bench->add_option("--frames", options.frames, "Frames timed per combination")
        ->check(CLI::Range(1, kMaxFrames))
        ->capture_default_str();
    bench
        ->add_option_function<std::string>(
            "--warmup",
            [&options](const std::string& text) {
                options.warmup = text == "auto" ? std::nullopt : std::optional(std::stoi(text));
            },
            "Frames rendered before timing (not counted), or auto: until the frame time settles (3 frames within "
            "10%, at most 1 s)")
        ->check(CLI::IsMember({"auto"}) | CLI::Range(0, kMaxFrames))
        ->default_str("auto");
    bench
        ->add_option("--fps", options.fps,
                     "Animate: frame k at scene time k/F, its posing timed with it (default: all at time 0)")
        ->check(numberIn(0.001, 1000.0));
    bench->add_option("--csv", options.csvPath, "Write one row per combination as CSV");
    bench->add_option("--json", options.jsonPath,
                      "Write the sweep as JSON, each pass with the clock it was timed on (- for stdout; the table "
                      "then goes to stderr)");
    bench
        ->add_option("--budget-ms", options.budgetMs,
                     "Skip a technique's larger light counts once its median frame exceeds this")
        ->check(numberIn(0.0, 1.0e9));
    bench->add_option("--plot", options.plotPath, "Write frame time against lights as an SVG plot")
        ->check([](const std::string& path) {
            return hasExtension(path, ".svg") ? std::string() : "must end in .svg, got '" + path + "'";
        });
    addGBufferOption(*bench, options.gbufferLayout);
    addAnisotropyOption(*bench, options.anisotropy);
    addDriverOptions(*bench, options.driver);
    addShadowOptions(*bench, options.shadows);
    addRebuildShadowsOption(*bench, options.rebuildShadows);
    bench->add_flag("--strict", options.strict, "Treat what model files get forgiven (warnings) as errors");
    addCameraOptions(*bench, options.camera);
    addDisplayOptions(*bench, options.display);
    bench->add_flag("--count-work", options.countWork,
                    "Also count light evaluations and in-range pairs (one extra, untimed frame each)");
    bench
        ->add_option_function<std::string>(
            "--shard", [&options](const std::string& text) { parseShard(text, options.shard); },
            "Time only the cases c (size, count, technique in sweep order) with c mod N = I-1 (I/N)")
        ->check([](const std::string& text) {
            Shard shard;
            std::string problem = parseShard(text, shard);
            const std::string name = "--shard ";  // CLI11 puts the option's name in front already
            if (problem.compare(0, name.size(), name) == 0)
                problem.erase(0, name.size());
            return problem;
        });
    return bench;
}

void runBench(const BenchOptions& options)
{
    const Scene scene = loadSceneForCommand(options.scenePath, options.strict, options.camera);
    // Before the sweep, which may take hours, rather than after it.
    if (!options.csvPath.empty())
        checkWritable(options.csvPath, "CSV");
    if (!options.plotPath.empty())
        checkWritable(options.plotPath, "plot");
    const bool jsonToStdout = options.jsonPath == "-";
    if (!options.jsonPath.empty() && !jsonToStdout)
        checkWritable(options.jsonPath, "JSON");

    const std::vector<std::string> techniques = options.techniques.empty() ? techniqueNames() : options.techniques;
    std::vector<std::optional<int>> lightCounts(options.lightCounts.begin(), options.lightCounts.end());
    if (lightCounts.empty())
        lightCounts.push_back(std::nullopt);

    const CullingTuning culling = cullingTuningFromEnvironment();
    HeadlessContext context({.debug = defaultDebugContext(), .device = options.driver.device});
    // What every Renderer below resolves the overrides to, for the header: the same context.
    const DriverChoices driver = resolveDriverChoices(options.driver.overrides);
    std::vector<BenchResult> results;
    {
        const std::size_t cases = options.sizes.size() * lightCounts.size() * techniques.size();
        std::size_t shardCases = 0;
        for (std::size_t c = 0; c < cases; ++c)
            shardCases += options.shard.has(c) ? 1 : 0;
        ProgressLine progress;
        std::size_t caseNumber = 0;
        std::size_t shardCase = 0;
        // Sizes outermost and techniques innermost: the techniques at one light count finish
        // together, so an interrupted sweep has compared them all up to where it stopped.
        for (const ImageSize& size : options.sizes) {
            std::set<std::string> overBudget;
            for (const std::optional<int>& count : lightCounts) {
                const std::vector<Light> lights = lightsForCommand(scene, count);
                for (const std::string& technique : techniques) {
                    if (!options.shard.has(caseNumber++))
                        continue;
                    const std::string label =
                        caseLabel(++shardCase, shardCases,
                                  technique + " " + std::to_string(lights.size()) + " lights " + formatSize(size));
                    if (overBudget.contains(technique)) {
                        progress.showAndLog(label + ": skipped, over the budget");
                        continue;
                    }
                    progress.show(label + " ...");
                    results.push_back(measure(scene, lights, technique, size, options, culling));
                    char ms[32];
                    std::snprintf(ms, sizeof ms, ": %.1f ms", results.back().measured.wallMs.median);
                    progress.showAndLog(label + ms);
                    if (options.budgetMs > 0.0 && results.back().measured.wallMs.median > options.budgetMs)
                        overBudget.insert(technique);
                }
            }
        }
    }

    const std::string_view profile = driverProfileName(driver.profile);
    char warmup[64] = "Warm-up until the frame time settled (auto)";
    if (options.warmup)
        std::snprintf(warmup, sizeof warmup, "%d warm-up frame%s", *options.warmup, *options.warmup == 1 ? "" : "s");
    // With the JSON on stdout, the table goes to stderr, so that stdout is one JSON document.
    std::FILE* table = jsonToStdout ? stderr : stdout;
    std::fprintf(table, "%s on %s, driver profile %.*s\n%s\n%s", scene.source.c_str(), context.description().c_str(),
                 int(profile.size()), profile.data(), clocksText(driver.passTiming, warmup, options.frames).c_str(),
                 tableText(results, options.countWork, driver.passTiming).c_str());
    std::fflush(table);
    // Both outputs or neither.
    AtomicFileSet outputs;
    if (!options.csvPath.empty())
        outputs.stage(options.csvPath, "CSV", csvText(results, options.shard.index == 1));
    std::string json;
    if (!options.jsonPath.empty()) {
        const auto glText = [](GLenum name) { return std::string(reinterpret_cast<const char*>(glGetString(name))); };
        json = jsonText(results,
                        {{"scene", scene.source},
                         {"device", context.description()},
                         {"gl_renderer", glText(GL_RENDERER)},
                         {"gl_version", glText(GL_VERSION)},
                         {"driver_profile", std::string(profile)},
                         {"pass_timing", std::string(passTimingName(driver.passTiming))},
                         {"warmup", options.warmup ? nlohmann::json(*options.warmup) : nlohmann::json("auto")},
                         {"frames", options.frames},
                         {"fps", options.fps ? nlohmann::json(*options.fps) : nlohmann::json(nullptr)},
                         {"shadow_lights", shadowLightsJson(chooseShadowLights(scene, options.shadows))},
                         {"shadow_pool_mib", options.shadows.poolMiB},
                         {"rebuild_shadows", options.rebuildShadows},
                         {"shard", std::to_string(options.shard.index) + "/" + std::to_string(options.shard.count)}});
        if (!jsonToStdout)
            outputs.stage(options.jsonPath, "JSON", json);
    }
    if (!options.plotPath.empty())
        outputs.stage(options.plotPath, "plot",
                      plotText(results, options, techniques, std::filesystem::path(scene.source).filename().string()));
    outputs.commit();
    if (jsonToStdout) {
        std::fputs(json.c_str(), stdout);
        std::fflush(stdout);
    }
}

}  // namespace manylights
