// What the subcommands share: the parsing of option values, the summary of timed frames and
// the reporting of errors. One definition each, so `render` and `bench` accept the same sizes
// and report the same statistics.
#pragma once

#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <new>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json_fwd.hpp>

#include "core/Error.h"

#include "apps/cli/OptionText.h"
#include "platform/EglChoice.h"
#include "render/Renderer.h"
#include "render/driver/DriverProfile.h"
#include "render/frame/GBuffer.h"
#include "render/frame/PassProfiler.h"
#include "scene/DisplaySettings.h"
#include "scene/Scene.h"
#include "scene/ShadowSelection.h"

namespace CLI {
class App;
class Validator;
}  // namespace CLI

namespace manylights {

// Exit statuses of docs/cli.md (0 on success).
inline constexpr int kExitFailure = 1;  // a bad scene, a broken asset, no OpenGL context, ...
inline constexpr int kExitUsage = 2;    // a bad command line

// Parses the command line into `app`'s options. Returns the status to exit with at once (0
// after --help; kExitUsage, the message printed, for a bad command line) or nothing to go on.
std::optional<int> parseCommandLine(CLI::App& app, int argc, const char* const* argv);

// Runs a parsed command: a user-facing failure is one line on stderr and exit status 1.
template <typename Command>
int reportingErrors(Command command, const std::string& activity)
{
    try {
        command();
    } catch (const Error& error) {
        std::fprintf(stderr, "manylights: %s\n", printableLine(error.what()).c_str());
        return kExitFailure;
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "manylights: out of memory %s\n", printableLine(activity).c_str());
        return kExitFailure;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "manylights: %s\n", printableLine(error.what()).c_str());
        return kExitFailure;
    }
    return 0;
}

// The defaults and bounds of the options `render`, `bench` and `view` share, each written once
// (--size's and the shadow options' text in apps/cli/OptionText.h).
inline constexpr std::string_view kDefaultTechnique = "clustered";  // --technique
// --lights: at most 2^24 lights, the bound docs/cli.md states for render, bench and view.
inline constexpr int kMaxLightCount = 16'777'216;

// --size WxH (one size), parsed into `size` as the command line is parsed.
void addSizeOption(CLI::App& command, ImageSize& size, const std::string& description);
// The check of one WxH (parseSize's problem, without the option's name: CLI11 adds it).
CLI::Validator sizeValidator();
// --technique NAME, one of techniqueNames().
void addTechniqueOption(CLI::App& command, std::string& technique);
// --lights N: the total count of the scene's light sets, replaced.
void addLightCountOption(CLI::App& command, std::optional<int>& lights);
// --gbuffer NAME: the deferred techniques' G-buffer layout; gbufferLayoutNames() lists them.
void addGBufferOption(CLI::App& command, GBufferLayout& layout);
std::vector<std::string> gbufferLayoutNames();

// An output image: its path and, from the path's extension (any case), its format.
enum class ImageFormat { Png, Pfm, Exr };
struct OutputImage {
    std::string path;
    ImageFormat format = ImageFormat::Png;
    bool eightBit() const { return format == ImageFormat::Png; }  // display-encoded; the others linear
};
// The format of `path`, or none when it ends in neither .png, .pfm nor .exr.
std::optional<ImageFormat> imageFormatOf(const std::string& path);
// Whether `path` ends in `extension` (".png", lower case), ignoring case: out.PNG is a PNG.
bool hasExtension(const std::filesystem::path& path, std::string_view extension);

// --anisotropy of render and bench: "auto", 1, 2, 4, 8 or 16, stored in `level` as
// TextureCache::setAnisotropy takes it (kAutoAnisotropy for "auto").
void addAnisotropyOption(CLI::App& command, int& level);

// --driver-profile, --pass-timing, --lighting-stage and --device of render, bench and view
// (docs/cli.md): what is asked of the renderer's driver seam (render/driver/DriverProfile.h),
// handed to RendererDesc::driver as it is, and which EGL device the renderer runs on
// (`manylights devices`), by index or UUID (platform/EglChoice.h: parseDeviceSelector).
struct DriverOptions {
    DriverOverrides overrides{};
    std::optional<DeviceSelector> device{};  // none: the first device that makes a context, hardware first
};
void addDriverOptions(CLI::App& command, DriverOptions& options);

// The culling's tuning for RendererDesc::culling from the environment (docs/cli.md,
// "Environment"): MANYLIGHTS_GLOBAL_LIGHT_FRACTION, MANYLIGHTS_MASKED_LIST_LIGHTS and
// MANYLIGHTS_CULLING_THREADS, each unset where its variable is. Throws manylights::Error naming
// the variable and its value for one that is not what it must be.
CullingTuning cullingTuningFromEnvironment();

// Median (the mean of the middle two for an even count), 95th percentile (nearest rank: the
// smallest value that at least 95% of them do not exceed), min and max; `values` not empty.
struct Statistics {
    double median = 0.0;
    double p95 = 0.0;
    double min = 0.0;
    double max = 0.0;
};
Statistics summarize(std::vector<double> values);

// The measured frames of render --frames and of one bench combination, summarised the same
// way for both: the frame's wall clock and timer-query times, and per pass (every frame runs
// the same passes in the same order) the medians and the last frame's fragment invocations.
struct PassSummary {
    std::string name;
    std::optional<double> wallMs;  // medians over the frames, where the frames' timing has them
    std::optional<double> gpuMs;
    std::optional<std::uint64_t> fragmentInvocations;
};
struct FrameSummary {
    PassTiming timing = PassTiming::Wall;  // how the frames were timed
    Statistics wallMs;                     // wall clock (FrameSample::wallMs says which interval)
    Statistics gpuMs;                      // between the frame's GL_TIMESTAMP queries
    std::vector<PassSummary> passes;
};
FrameSummary summarizeFrames(const std::vector<FrameSample>& frames);

// The camera options of render, bench and view (docs/cli.md): a model file's camera by name
// or index, then any of its parts replaced.
struct CameraOptions {
    std::string camera;               // --camera NAME|INDEX: one of Scene::cameras
    std::optional<glm::vec3> eye;     // --eye X,Y,Z
    std::optional<glm::vec3> lookAt;  // --look-at X,Y,Z
    std::optional<glm::vec3> up;      // --up X,Y,Z
    std::optional<float> fovY;        // --fov-y DEGREES
};
void addCameraOptions(CLI::App& command, CameraOptions& options);
// The scene's camera with `options` applied. Throws manylights::Error for a camera the scene
// does not have (naming those it has) or a view that is not one (eye at look-at, up along it).
Camera chooseCamera(const Scene& scene, const CameraOptions& options);
// The command line that gives `camera`: "--eye X,Y,Z --look-at X,Y,Z --up X,Y,Z --fov-y D".
std::string cameraCommandLine(const Camera& camera);

// The display options of render, bench and view (docs/display.md): each replaces the
// scene's `display` setting when given.
struct DisplayOptions {
    std::optional<float> exposure;             // --exposure EV
    std::optional<ToneCurve> toneCurve;        // --tonemap NAME
    std::optional<bool> srgb;                  // --srgb / --no-srgb
    std::optional<Antialiasing> antialiasing;  // --aa NAME
};
void addDisplayOptions(CLI::App& command, DisplayOptions& options);
// The scene's display settings with `options` applied.
DisplaySettings chooseDisplay(const Scene& scene, const DisplayOptions& options);

// The shadow options of render, bench and view (docs/cli.md, docs/shadows.md): every local
// light may cast a shadow through the shadow-page pool, which has no budget of lights.
struct ShadowOptions {
    // --shadow-lights N|all: how many local lights cast shadows, kAllShadowLights for all;
    // none: the scene's "shadow_lights", else 0 (chooseShadowLights).
    std::optional<int> lights;
    int poolMiB = kDefaultShadowPoolMiB;  // --shadow-pool-mib N: the shadow-page pool's size
};
// --shadow-lights and --shadow-pool-mib.
void addShadowOptions(CLI::App& command, ShadowOptions& options);
// --rebuild-shadows of render and bench (RendererDesc::rebuildShadowsEveryFrame).
void addRebuildShadowsOption(CLI::App& command, bool& rebuild);
// RendererDesc::shadowLights: --shadow-lights, else the scene's "shadow_lights", else 0.
int chooseShadowLights(const Scene& scene, const ShadowOptions& options);
// A shadowLights value as render's --stats and bench's --json write it: "all", or the count.
nlohmann::json shadowLightsJson(int lights);

// The scene at `path` (the built-in default scene when empty), with --strict passed on and the
// camera options applied; every problem the loading forgave is printed on stderr as
// "manylights: warning: ..." (one line).
Scene loadSceneForCommand(const std::string& path, bool strict, const CameraOptions& camera = {});
// Prints each of `warnings` on stderr as "manylights: warning: ..." (one line each): the
// scene's, and what the renderer's loading forgave (EnvironmentLight::warnings).
void printWarnings(const std::vector<std::string>& warnings);

// Whether two output paths name one file (out.png and ./out.png; a link and its target).
bool sameFile(const std::string& a, const std::string& b);

// The check of every real-valued option: a finite number in [min, max] (core/Numbers.h).
CLI::Validator numberIn(double min, double max);

}  // namespace manylights
