#include "apps/cli/RenderCommand.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/cli/CommandSupport.h"
#include "apps/cli/Progress.h"
#include "core/AtomicFile.h"
#include "core/Error.h"
#include "platform/HeadlessContext.h"
#include "render/HeatMapLegend.h"
#include "render/Renderer.h"
#include "render/output/ExrFile.h"
#include "scene/LightSets.h"

namespace manylights {

namespace {

// Frames rendered before measuring when timings are asked for: the first frame pays for
// shader compilation and first-use allocations in the driver.
constexpr int kWarmupFrames = 1;

// Which clock each time of --stats reads, and over what (docs/cli.md): the answer depends on
// how the frames were timed (render/frame/PassProfiler.h).
nlohmann::json timesJson(PassTiming timing)
{
    nlohmann::json times;
    times["frame_ms"] = timing == PassTiming::Wall
                            ? "CPU clock, from a glFinish before the frame to one after it"
                            : "CPU clock, from the frame's start until the CPU saw the GPU finish it";
    times["frame_gpu_ms"] = "GPU clock, between GL_TIMESTAMP queries at the frame's start and end";
    times["gpu_ms"] = timing == PassTiming::Frame ? "none: --pass-timing frame makes no per-pass queries"
                                                  : "GPU clock, GL_TIME_ELAPSED around the pass";
    times["wall_ms"] = timing == PassTiming::Wall ? "CPU clock, from a glFinish before the pass to one after it"
                                                  : "none: only --pass-timing wall waits for each pass";
    return times;
}

// `desc`: what the renderer was made with (the settings the command resolved from its options
// and the scene).
nlohmann::json statisticsJson(const RenderOptions& options, const Scene& scene, const RendererDesc& desc,
                              std::size_t lightCount, const std::vector<FrameSample>& frames, const std::string& device,
                              float anisotropy, const DriverChoices& driver, const Technique& technique,
                              const WorkCounts* work)
{
    nlohmann::json stats;
    stats["technique"] = options.technique;
    stats["gbuffer"] = std::string(gbufferLayoutName(options.gbufferLayout));
    stats["view"] = std::string(viewModeName(options.view));
    stats["scene"] = scene.source;
    stats["device"] = device;
    stats["width"] = options.size.width;
    stats["height"] = options.size.height;
    stats["lights"] = lightCount;
    stats["frames"] = frames.size();
    stats["shadow_lights"] = shadowLightsJson(desc.shadowLights);
    stats["shadow_pool_mib"] = desc.shadowPoolMiB;
    stats["anisotropy"] = anisotropy;
    stats["driver_profile"] = std::string(driverProfileName(driver.profile));
    stats["lighting_stage"] = std::string(lightingStageName(technique.options().lightingStage));
    stats["warmup_frames"] = kWarmupFrames;
    stats["warnings"] = scene.warnings.size();
    const auto summaryJson = [](const Statistics& statistics) {
        return nlohmann::json{
            {"median", statistics.median}, {"p95", statistics.p95}, {"min", statistics.min}, {"max", statistics.max}};
    };
    const auto optionalJson = [](const auto& value) {
        return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
    };
    const FrameSummary summary = summarizeFrames(frames);
    stats["pass_timing"] = std::string(passTimingName(summary.timing));
    stats["times"] = timesJson(summary.timing);
    stats["frame_ms"] = summaryJson(summary.wallMs);
    stats["frame_gpu_ms"] = summaryJson(summary.gpuMs);
    nlohmann::json passes = nlohmann::json::array();
    for (const PassSummary& pass : summary.passes)
        passes.push_back({{"name", pass.name},
                          {"gpu_ms", optionalJson(pass.gpuMs)},
                          {"wall_ms", optionalJson(pass.wallMs)},
                          {"fragment_invocations", optionalJson(pass.fragmentInvocations)}});
    stats["passes"] = passes;
    for (const TechniqueCounter& counter : technique.counters())
        stats[counter.name] = counter.value;
    if (work) {
        stats["light_evaluations"] = work->lightEvaluations;
        stats["transparent_light_evaluations"] = work->transparentLightEvaluations;
        stats["in_range_pairs"] = work->inRangePairs;
    }
    return stats;
}

// The layers --aovs adds to an EXR file: each G-buffer view under its --view name, with
// the channel names compositing tools expect for its kind of quantity.
struct AovLayer {
    ViewMode view;
    std::vector<std::string> channels;
};
const std::vector<AovLayer>& aovLayers()
{
    static const std::vector<AovLayer> layers{
        {ViewMode::Position, {"X", "Y", "Z"}},
        {ViewMode::Normal, {"X", "Y", "Z"}},
        {ViewMode::Diffuse, {"R", "G", "B"}},
        {ViewMode::Specular, {"R", "G", "B"}},
        {ViewMode::Emissive, {"R", "G", "B"}},
        {ViewMode::Depth, {"Z"}},
        {ViewMode::LightCount, {"Y"}},
        {ViewMode::Shadow, {"Y"}},
        {ViewMode::Ssao, {"Y"}},
    };
    return layers;
}

// The renderer's last frame encoded as the output's format: .pfm and .exr as linear floats (box-filtered
// down when supersampled), .png through the display pass (the final and volumes views) or as
// the view's displayable image (the light-count and shadow-resolution views' with their legends unless
// --no-legend). --aovs renders each
// G-buffer view after the frame and adds it to the EXR file (the renderer then holds the last view's frame: nothing
// reads it after).
std::string encodeLastFrame(Renderer& renderer, Technique& technique, const RenderOptions& options)
{
    const ViewMode view = options.view;
    if (options.output.eightBit()) {
        if (showsFinalImage(view))
            return encodePng(renderer.readDisplayed());
        const Image raw = renderer.readColour();
        Image shown = displayableView(raw, view, renderer.readCoverage());
        if (options.legend)
            drawViewLegend(shown, raw, view, options.technique);
        return encodePng(shown);
    }
    Image linear = boxDownsample(renderer.readColour(), options.supersample);
    if (options.output.format == ImageFormat::Pfm)
        return encodePfm(linear);
    std::vector<ExrLayer> layers{{"", {"R", "G", "B"}, std::move(linear)}};
    if (options.aovs) {
        for (const AovLayer& aov : aovLayers()) {
            renderer.renderFrame(technique, aov.view);
            layers.push_back({std::string(viewModeName(aov.view)), aov.channels,
                              boxDownsample(renderer.readColour(), options.supersample)});
        }
    }
    return encodeExr(layers, options.exrFloat ? ExrPixels::Float : ExrPixels::Half);
}

// The frames of the time range this run renders: its shard's, less those whose files exist
// when --skip-existing (outputs are written atomically, so an existing file is whole).
std::vector<int> framesToRecord(const RenderOptions& options)
{
    const int count = recordingFrameCount(*options.timeRange, options.fps);
    std::vector<int> frames;
    for (int frame = 0; frame < count; ++frame) {
        if (!options.shard.has(static_cast<std::size_t>(frame)))
            continue;
        std::error_code error;
        if (options.skipExisting && std::filesystem::exists(formatFramePath(options.output.path, frame), error))
            continue;
        frames.push_back(frame);
    }
    return frames;
}

// The given frames of the time range, each written atomically under its own name as soon as
// it is rendered: an interrupted recording leaves whole frames only. A frame is a pure
// function of its time, so any subset gives the same files as the whole recording.
void recordFrames(Renderer& renderer, Technique& technique, const RenderOptions& options,
                  const std::vector<int>& frames)
{
    const int count = static_cast<int>(frames.size());
    ProgressLine progress;
    printRecordingProgress(progress, 0, count);
    for (int done = 0; done < count; ++done) {
        const int frame = frames[static_cast<std::size_t>(done)];
        renderer.setTime(recordingFrameTime(*options.timeRange, options.fps, frame));
        renderer.renderFrame(technique, options.view);
        const std::string path = formatFramePath(options.output.path, frame);
        writeFileAtomically(path, "image", encodeLastFrame(renderer, technique, options));
        printRecordingProgress(progress, done + 1, count);
    }
}

}  // namespace

void runRender(const RenderOptions& options)
{
    // Fail in a second, before loading and rendering, when an output cannot be written; a
    // recording's folder is made as other tools make theirs.
    std::vector<int> recorded;
    if (options.timeRange) {
        const std::filesystem::path first = formatFramePath(options.output.path, 0);
        createOutputFolder(first);
        checkWritable(first, "image");
        recorded = framesToRecord(options);
        if (recorded.empty()) {
            std::fprintf(stderr, "manylights: every frame of this recording%s exists already (--skip-existing)\n",
                         options.shard.isWhole() ? "" : "'s shard");
            return;
        }
    } else {
        checkWritable(options.output.path, "image");
        if (!options.statsPath.empty())
            checkWritable(options.statsPath, "statistics");
    }
    const auto loadStart = std::chrono::steady_clock::now();
    const Scene scene = loadSceneForCommand(options.scenePath, options.strict, options.camera);
    const double loadMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - loadStart).count();
    const auto millisecondsSince = [](std::chrono::steady_clock::time_point start) {
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    };
    const auto lightsStart = std::chrono::steady_clock::now();
    const std::vector<Light> lights = lightsForCommand(scene, options.lights);
    const double lightsMs = millisecondsSince(lightsStart);

    HeadlessContext context({.debug = defaultDebugContext(), .device = options.driver.device});
    const auto rendererStart = std::chrono::steady_clock::now();
    const DisplaySettings display = chooseDisplay(scene, options.display);
    const bool countWork = options.countWork || options.view == ViewMode::LightCount || options.aovs;
    Renderer renderer(scene, lights,
                      {.width = options.size.width * options.supersample,
                       .height = options.size.height * options.supersample,
                       .gbufferLayout = options.gbufferLayout,
                       .countWork = countWork,
                       .shadowLights = chooseShadowLights(scene, options.shadows),
                       .shadowPoolMiB = options.shadows.poolMiB,
                       .rebuildShadowsEveryFrame = options.rebuildShadows,
                       .anisotropy = options.anisotropy,
                       .display = options.output.eightBit() ? std::optional(display) : std::nullopt,
                       .supersample = options.supersample,
                       .driver = options.driver.overrides,
                       .culling = cullingTuningFromEnvironment()});
    printWarnings(renderer.gpuScene().environment().warnings());
    renderer.setTime(options.time);
    Technique& technique = renderer.technique(options.technique);
    // The scene on the GPU (lights, meshes, textures, their upload) and the technique's programs.
    const double rendererMs = millisecondsSince(rendererStart);

    if (options.timeRange) {
        recordFrames(renderer, technique, options, recorded);
        return;
    }

    const bool measuring = !options.statsPath.empty();
    // A frame at 1920x1080 with thousands of lights can take minutes on a software rasteriser:
    // on a terminal, a status line says what is running (erased when done); logs stay clean.
    ProgressLine progress;
    const int total = options.frames + (measuring ? kWarmupFrames : 0);
    int started = 0;
    const auto renderOneFrame = [&] {
        progress.show("rendering frame " + std::to_string(++started) + "/" + std::to_string(total) + " (" +
                      options.technique + ", " + formatSize(options.size) + ") ...");
        FrameSample sample = renderer.renderFrame(technique, options.view);
        if (started == total)
            progress.erase();
        return sample;
    };
    for (int i = 0; measuring && i < kWarmupFrames; ++i)
        renderOneFrame();
    std::vector<FrameSample> frames;
    for (int i = 0; i < options.frames; ++i)
        frames.push_back(renderOneFrame());

    // The image and the statistics appear together or not at all.
    AtomicFileSet outputs;
    // The work counts before --aovs renders its views.
    const WorkCounts work = renderer.lastWorkCounts();
    outputs.stage(options.output.path, "image", encodeLastFrame(renderer, technique, options));
    if (measuring) {
        nlohmann::json stats =
            statisticsJson(options, scene, renderer.desc(), lights.size(), frames, context.description(),
                           renderer.anisotropy(), renderer.driverChoices(), technique, countWork ? &work : nullptr);
        stats["display"] = {{"exposure", display.exposure},
                            {"tonemap", std::string(toneCurveName(display.toneCurve))},
                            {"srgb", display.srgb},
                            {"aa", std::string(antialiasingName(display.antialiasing))},
                            {"supersample", options.supersample},
                            {"applied", options.output.eightBit()}};
        // The shadow-page pool's figures of the last frame (docs/shadows.md).
        for (const TechniqueCounter& counter : renderer.shadowPool().counters())
            stats[counter.name] = counter.value;
        stats["load_ms"] = loadMs;
        stats["lights_ms"] = lightsMs;
        stats["renderer_ms"] = rendererMs;
        const EnvironmentLight& environment = renderer.gpuScene().environment();
        stats["environment_ms"] = environment.present() ? nlohmann::json(environment.loadMs()) : nlohmann::json();
        outputs.stage(options.statsPath, "statistics", stats.dump(2) + "\n");
    }
    outputs.commit();
}

}  // namespace manylights
