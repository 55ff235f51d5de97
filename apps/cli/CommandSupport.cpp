#include "apps/cli/CommandSupport.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "core/AtomicFile.h"
#include "core/Error.h"
#include "core/Numbers.h"
#include "render/Techniques.h"
#include "render/culling/ClusterLists.h"
#include "render/culling/TileCulling.h"
#include "render/output/Image.h"
#include "render/scene/TextureCache.h"
#include "render/techniques/Technique.h"
#include "scene/DefaultScene.h"
#include "scene/SceneLoader.h"

namespace manylights {

CLI::Validator sizeValidator()
{
    return CLI::Validator(
        [](const std::string& text) {
            ImageSize size;
            std::string problem = parseSize(text, size);
            // CLI11 puts the option's name in front already.
            const std::string name = "--size ";
            if (problem.compare(0, name.size(), name) == 0)
                problem.erase(0, name.size());
            return problem;
        },
        "WxH");
}

void addSizeOption(CLI::App& command, ImageSize& size, const std::string& description)
{
    command
        .add_option_function<std::string>(
            "--size", [&size](const std::string& text) { parseSize(text, size); },  // the check has accepted it
            description)
        ->check(sizeValidator())
        ->default_str(formatSize(kDefaultImageSize));
}

void addTechniqueOption(CLI::App& command, std::string& technique)
{
    command.add_option("--technique", technique, "Lighting technique")
        ->check(CLI::IsMember(techniqueNames()))
        ->capture_default_str();
}

void addLightCountOption(CLI::App& command, std::optional<int>& lights)
{
    command.add_option("--lights", lights, "Replace the total count of the scene's light sets")
        ->check(CLI::Range(0, kMaxLightCount));
}

std::vector<std::string> gbufferLayoutNames()
{
    return {std::string(gbufferLayoutName(GBufferLayout::Seed)),
            std::string(gbufferLayoutName(GBufferLayout::Compact))};
}

void addGBufferOption(CLI::App& command, GBufferLayout& layout)
{
    command
        .add_option_function<std::string>(
            "--gbuffer", [&layout](const std::string& name) { layout = *parseGBufferLayout(name); },
            "G-buffer layout of the deferred techniques")
        ->check(CLI::IsMember(gbufferLayoutNames()))
        ->default_str(std::string(gbufferLayoutName(kDefaultGBufferLayout)));
}

bool hasExtension(const std::filesystem::path& path, std::string_view extension)
{
    std::string actual = path.extension().string();
    std::transform(actual.begin(), actual.end(), actual.begin(), [](unsigned char c) { return std::tolower(c); });
    return actual == extension;
}

std::optional<ImageFormat> imageFormatOf(const std::string& path)
{
    if (hasExtension(path, ".png"))
        return ImageFormat::Png;
    if (hasExtension(path, ".pfm"))
        return ImageFormat::Pfm;
    if (hasExtension(path, ".exr"))
        return ImageFormat::Exr;
    return std::nullopt;
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

void addDriverOptions(CLI::App& command, DriverOptions& options)
{
    command
        .add_option_function<std::string>(
            "--driver-profile",
            [&options](const std::string& name) { options.overrides.profile = *parseDriverProfile(name); },
            "Make the choices of a software rasteriser or of a GPU driver (auto: by the driver in use)")
        ->check(CLI::IsMember(namesOf(kDriverProfileNames)))
        ->default_str(std::string(driverProfileName(DriverProfile::Auto)));
    command
        .add_option_function<std::string>(
            "--device",
            [&options](const std::string& text) {
                DeviceSelector selector;
                parseDeviceSelector(text, selector);  // the check has accepted it
                options.device = selector;
            },
            "Render on EGL device N, or on the device with this UUID (manylights devices lists both)")
        ->check(CLI::Validator(
            [](const std::string& text) {
                DeviceSelector selector;
                return parseDeviceSelector(text, selector);
            },
            "N|UUID"));
    command
        .add_option_function<std::string>(
            "--pass-timing",
            [&options](const std::string& name) { options.overrides.passTiming = *parsePassTiming(name); },
            "How frames are timed: wall (a glFinish around every pass), gpu (timer queries, frames back to back), "
            "frame (gpu without the per-pass queries); default: wall on a software rasteriser, gpu on a GPU")
        ->check(CLI::IsMember(namesOf(kPassTimingNames)));
    command
        .add_option_function<std::string>(
            "--lighting-stage",
            [&options](const std::string& name) { options.overrides.lightingStage = *parseLightingStage(name); },
            "deferred's and clustered's lighting as a full-screen fragment pass or a compute pass; default: "
            "fragment on a software rasteriser, compute on a GPU")
        ->check(CLI::IsMember(namesOf(kLightingStageNames)));
}

CullingTuning cullingTuningFromEnvironment()
{
    CullingTuning tuning;
    if (const char* text = std::getenv("MANYLIGHTS_GLOBAL_LIGHT_FRACTION")) {
        char* end = nullptr;
        const double value = std::strtod(text, &end);
        if (end == text || *end != '\0' || !(value > 0.0) || !std::isfinite(value))
            throw Error(std::string("MANYLIGHTS_GLOBAL_LIGHT_FRACTION: expected a number > 0, got '") + text + "'");
        tuning.globalLightGridFraction = value;
    }
    if (const char* text = std::getenv("MANYLIGHTS_MASKED_LIST_LIGHTS")) {
        const std::optional<unsigned long> value = wholeNumberIn(text, 0, kMaskedListLights);
        if (!value)
            throw Error("MANYLIGHTS_MASKED_LIST_LIGHTS: expected a whole number of lights up to " +
                        std::to_string(kMaskedListLights) + ", got '" + text + "'");
        tuning.maskedListLights = static_cast<std::uint32_t>(*value);
    }
    if (const char* text = std::getenv("MANYLIGHTS_CULLING_THREADS")) {
        const std::optional<unsigned long> value = wholeNumberIn(text, 1, kMaxCullingThreads);
        if (!value)
            throw Error("MANYLIGHTS_CULLING_THREADS: expected a whole number of threads from 1 to " +
                        std::to_string(kMaxCullingThreads) + ", got '" + text + "'");
        tuning.cullingThreads = static_cast<unsigned>(*value);
    }
    return tuning;
}

FrameSummary summarizeFrames(const std::vector<FrameSample>& frames)
{
    ML_ASSERT(!frames.empty());
    FrameSummary summary;
    summary.timing = frames.back().timing;
    std::vector<double> wallMs;
    std::vector<double> gpuMs;
    for (const FrameSample& frame : frames) {
        wallMs.push_back(frame.wallMs);
        gpuMs.push_back(frame.gpuMs);
    }
    summary.wallMs = summarize(wallMs);
    summary.gpuMs = summarize(gpuMs);
    // The median of a pass's times over the frames that have them.
    const auto passMedian = [&](std::size_t p, std::optional<double> PassSample::*time) -> std::optional<double> {
        std::vector<double> times;
        for (const FrameSample& frame : frames)
            if (p < frame.passes.size() && frame.passes[p].*time)
                times.push_back(*(frame.passes[p].*time));
        return times.empty() ? std::nullopt : std::optional(summarize(times).median);
    };
    for (std::size_t p = 0; p < frames.back().passes.size(); ++p) {
        const PassSample& last = frames.back().passes[p];
        summary.passes.push_back({last.name, passMedian(p, &PassSample::wallMs), passMedian(p, &PassSample::gpuMs),
                                  last.fragmentInvocations});
    }
    return summary;
}

Statistics summarize(std::vector<double> values)
{
    ML_ASSERT(!values.empty());
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    const double median = n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
    // Nearest rank: the ceil(0.95 n)-th smallest.
    const std::size_t rank = (95 * n + 99) / 100;
    return {median, values[rank - 1], values.front(), values.back()};
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

namespace {

// "X,Y,Z": three finite numbers of at most 1e30 (a scene's coordinates are floats).
std::string parseVector(const std::string& text, glm::vec3& vector)
{
    std::size_t begin = 0;
    for (int i = 0; i < 3; ++i) {
        const std::size_t comma = i < 2 ? text.find(',', begin) : text.size();
        if (comma == std::string::npos)
            return "must be three numbers X,Y,Z, got '" + text + "'";
        double value = 0.0;
        if (!checkNumber(std::string_view(text).substr(begin, comma - begin), -1.0e30, 1.0e30, value).empty())
            return "must be three numbers X,Y,Z from -1e+30 to 1e+30, got '" + text + "'";
        vector[i] = static_cast<float>(value);
        begin = comma + 1;
    }
    return {};
}

}  // namespace

void addCameraOptions(CLI::App& command, CameraOptions& options)
{
    command.add_option("--camera", options.camera,
                       "View through a camera of the scene's model files, by name or index (see docs/cli.md)");
    const auto vectorOption = [&](const char* name, std::optional<glm::vec3>& target, const char* description) {
        command
            .add_option_function<std::string>(
                name, [&target](const std::string& text) { parseVector(text, target.emplace()); }, description)
            ->check(CLI::Validator(
                [](const std::string& text) {
                    glm::vec3 ignored;
                    return parseVector(text, ignored);
                },
                "X,Y,Z"));
    };
    vectorOption("--eye", options.eye, "Camera position X,Y,Z, replacing the scene's");
    vectorOption("--look-at", options.lookAt, "Point the camera looks at X,Y,Z, replacing the scene's");
    vectorOption("--up", options.up, "Camera up direction X,Y,Z, replacing the scene's");
    command
        .add_option_function<double>(
            "--fov-y", [&options](double degrees) { options.fovY = static_cast<float>(degrees); },
            "Vertical field of view in degrees, replacing the scene's")
        ->check(numberIn(0.001, 179.999));
}

void addDisplayOptions(CLI::App& command, DisplayOptions& options)
{
    command
        .add_option_function<double>(
            "--exposure", [&options](double stops) { options.exposure = static_cast<float>(stops); },
            "Exposure in stops: the linear colour times 2^EV before the tone curve (default: the scene's, else 0)")
        ->check(numberIn(-kMaxExposureStops, kMaxExposureStops));
    CLI::Option* tonemap =
        command
            .add_option_function<std::string>(
                "--tonemap", [&options](const std::string& name) { options.toneCurve = parseToneCurve(name); },
                "Tone curve of 8-bit outputs and the window (default: the scene's, else pbr-neutral)")
            ->check(CLI::IsMember(toneCurveNames()));
    CLI::Option* srgb = command.add_flag_callback(
        "--srgb", [&options] { options.srgb = true; },
        "Encode 8-bit outputs and the window with the sRGB curve (default: the scene's, else on)");
    CLI::Option* noSrgb = command.add_flag_callback(
        "--no-srgb", [&options] { options.srgb = false; }, "Write 8-bit outputs linear, without the sRGB curve");
    srgb->excludes(noSrgb);
    CLI::Option* classic = command.add_flag_callback(
        "--classic",
        [&options] {
            options.toneCurve = ToneCurve::None;
            options.srgb = false;
        },
        "The classic look, round(255 * clamp(colour, 0, 1)): short for --tonemap none --no-srgb");
    classic->excludes(tonemap)->excludes(srgb)->excludes(noSrgb);
    command
        .add_option_function<std::string>(
            "--aa", [&options](const std::string& name) { options.antialiasing = parseAntialiasing(name); },
            "Anti-aliasing of 8-bit outputs and the window (default: the scene's, else none)")
        ->check(CLI::IsMember(antialiasingNames()));
}

void addShadowOptions(CLI::App& command, ShadowOptions& options)
{
    command
        .add_option_function<std::string>(
            "--shadow-lights",
            [&options](const std::string& text) { parseShadowLights(text, options.lights.emplace()); },
            "Local lights that cast shadows, all or the N with the largest screen coverage x intensity (default: the "
            "scene's shadowLights, else 0)")
        ->check(CLI::Validator(
            [](const std::string& text) {
                int ignored = 0;
                return parseShadowLights(text, ignored);
            },
            "N|all"));
    command
        .add_option_function<std::string>(
            "--shadow-pool-mib", [&options](const std::string& text) { parseShadowPoolMiB(text, options.poolMiB); },
            "Size of the shadow-page pool in MiB, a multiple of " + std::to_string(kShadowPoolGrainMiB) + " from " +
                std::to_string(kMinShadowPoolMiB) + " to " + std::to_string(kMaxShadowPoolMiB))
        ->check(CLI::Validator(
            [](const std::string& text) {
                int ignored = 0;
                return parseShadowPoolMiB(text, ignored);
            },
            "MIB"))
        ->default_str(std::to_string(kDefaultShadowPoolMiB));
}

void addRebuildShadowsOption(CLI::App& command, bool& rebuild)
{
    command.add_flag("--rebuild-shadows", rebuild,
                     "Draw every shadow page every frame instead of reusing unchanged ones (to time them)");
}

int chooseShadowLights(const Scene& scene, const ShadowOptions& options)
{
    return options.lights.value_or(scene.shadowLights.value_or(0));
}

nlohmann::json shadowLightsJson(int lights)
{
    return lights == kAllShadowLights ? nlohmann::json("all") : nlohmann::json(lights);
}

DisplaySettings chooseDisplay(const Scene& scene, const DisplayOptions& options)
{
    DisplaySettings settings = scene.display;
    settings.exposure = options.exposure.value_or(settings.exposure);
    settings.toneCurve = options.toneCurve.value_or(settings.toneCurve);
    settings.srgb = options.srgb.value_or(settings.srgb);
    settings.antialiasing = options.antialiasing.value_or(settings.antialiasing);
    return settings;
}

Camera chooseCamera(const Scene& scene, const CameraOptions& options)
{
    Camera camera = scene.camera;
    if (!options.camera.empty()) {
        const NamedCamera* chosen = nullptr;
        for (const NamedCamera& named : scene.cameras)
            if (named.name == options.camera)
                chosen = &named;
        double index = 0.0;
        if (!chosen && checkNumber(options.camera, 0.0, 1.0e9, index).empty() && index == std::floor(index) &&
            index < static_cast<double>(scene.cameras.size()))
            chosen = &scene.cameras[static_cast<std::size_t>(index)];
        if (!chosen) {
            std::string names;
            for (const NamedCamera& named : scene.cameras)
                names += (names.empty() ? "" : ", ") + named.name;
            throw Error(scene.source + ": --camera '" + options.camera + "': no such camera (" +
                        (names.empty() ? std::string("the scene's model files define none")
                                       : "it has " + std::to_string(scene.cameras.size()) + ": " + names) +
                        ")");
        }
        camera = chosen->camera;
    }
    camera.eye = options.eye.value_or(camera.eye);
    camera.lookAt = options.lookAt.value_or(camera.lookAt);
    camera.up = options.up.value_or(camera.up);
    camera.fovYDegrees = options.fovY.value_or(camera.fovYDegrees);
    if (const CameraProblem problem = cameraProblem(camera); problem != CameraProblem::None)
        throw Error("the camera of --eye, --look-at, --up and --camera (the scene's for what they leave out): " +
                    std::string(describe(problem)));
    return camera;
}

std::string cameraCommandLine(const Camera& camera)
{
    // Nine significant digits: a float printed and read back is the same float.
    const auto number = [](float value) {
        char text[32];
        std::snprintf(text, sizeof text, "%.9g", static_cast<double>(value));
        return std::string(text);
    };
    const auto vector = [&](const glm::vec3& v) { return number(v.x) + "," + number(v.y) + "," + number(v.z); };
    return "--eye " + vector(camera.eye) + " --look-at " + vector(camera.lookAt) + " --up " + vector(camera.up) +
           " --fov-y " + number(camera.fovYDegrees);
}

Scene loadSceneForCommand(const std::string& path, bool strict, const CameraOptions& camera)
{
    Scene scene = path.empty() ? makeDefaultScene() : loadSceneFile(path, {.strict = strict});
    printWarnings(scene.warnings);
    scene.camera = chooseCamera(scene, camera);
    return scene;
}

void printWarnings(const std::vector<std::string>& warnings)
{
    for (const std::string& warning : warnings)
        std::fprintf(stderr, "manylights: warning: %s\n", printableLine(warning).c_str());
}

bool sameFile(const std::string& a, const std::string& b)
{
    std::error_code error;
    const auto resolved = [&](const std::string& path) {
        return std::filesystem::weakly_canonical(std::filesystem::absolute(path, error), error);
    };
    return resolved(a) == resolved(b);
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
