// The one seam for what varies by driver (issues 30 and 46): the choices the renderer makes by
// the kind of driver it runs on, what was measured fastest on a software rasteriser (Mesa's
// llvmpipe) and what the vendors advise on a GPU. --driver-profile (docs/cli.md) picks them by
// name, so that the GPU's code paths are tested on llvmpipe and the other way round; `auto`
// picks them by GL_RENDERER. --pass-timing and --lighting-stage override one choice each.
//
// The commands carry a DriverOverrides in RendererDesc::driver, and the Renderer resolves it
// once (resolveDriverChoices) into the DriverChoices it owns. Code that behaves differently on
// a GPU reads a field of DriverChoices, never the driver's name, and never merges an override
// with the profile again. This is the bottom room of render/ (scripts/check-layers.sh): every
// other room may read the choices.
#pragma once

#include <optional>
#include <string_view>

#include "core/EnumNames.h"

namespace manylights {

enum class DriverProfile { Auto, Software, Gpu };
inline constexpr EnumNames<DriverProfile, 3> kDriverProfileNames{{
    {DriverProfile::Auto, "auto"},
    {DriverProfile::Software, "software"},
    {DriverProfile::Gpu, "gpu"},
}};
inline std::string_view driverProfileName(DriverProfile profile) { return nameOf(kDriverProfileNames, profile); }
inline std::optional<DriverProfile> parseDriverProfile(std::string_view name)
{
    return parseName(kDriverProfileNames, name);
}

// How frames are timed (render/frame/PassProfiler.h). Two clocks, because neither is right
// everywhere: GL timer queries are what a GPU profiler shows, but llvmpipe records them when it
// bins commands, not when its threads rasterise, so it under-reports passes with many draws by
// up to 10x; the wall clock between glFinish calls is exact on llvmpipe (the GPU is the CPU),
// but on a GPU each glFinish drains the GPU, so a frame timed that way is a frame no
// application runs (docs/performance.md, "Timing on a GPU").
enum class PassTiming {
    // A glFinish before and after every pass: each pass's wall-clock time is its own, and
    // frames run one at a time. What a software rasteriser needs.
    Wall,
    // Timer queries around every pass and no glFinish anywhere: frames are issued back to back
    // and each pass's GPU time is read once the GPU has run it, a frame or more later.
    Gpu,
    // Gpu without the per-pass queries: only the frame's two timestamps. The frame as it runs
    // without the profiler, to see what the per-pass queries cost.
    Frame,
};
inline constexpr EnumNames<PassTiming, 3> kPassTimingNames{{
    {PassTiming::Wall, "wall"},
    {PassTiming::Gpu, "gpu"},
    {PassTiming::Frame, "frame"},
}};
inline std::string_view passTimingName(PassTiming timing) { return nameOf(kPassTimingNames, timing); }
inline std::optional<PassTiming> parsePassTiming(std::string_view name) { return parseName(kPassTimingNames, name); }

// Where deferred's and clustered's lighting runs (--lighting-stage): a full-screen fragment
// pass, or a compute pass of an invocation per pixel that stores into the lit image. The
// other techniques have one stage only (tiled computes; forward, the volumes and tiled-quads
// rasterise) and ignore it.
enum class LightingStage { Fragment, Compute };
inline constexpr EnumNames<LightingStage, 2> kLightingStageNames{{
    {LightingStage::Fragment, "fragment"},
    {LightingStage::Compute, "compute"},
}};
inline std::string_view lightingStageName(LightingStage stage) { return nameOf(kLightingStageNames, stage); }
inline std::optional<LightingStage> parseLightingStage(std::string_view name)
{
    return parseName(kLightingStageNames, name);
}

// What a command asks of the driver seam: the profile (--driver-profile) and the choices it
// overrides (--pass-timing, --lighting-stage); an unset override is the profile's choice.
struct DriverOverrides {
    DriverProfile profile = DriverProfile::Auto;
    std::optional<PassTiming> passTiming{};
    std::optional<LightingStage> lightingStage{};

    bool operator==(const DriverOverrides&) const = default;
};

// The anisotropy the texture units filter with where filtering costs nearly nothing (a GPU):
// oblique textures stay sharp (render/scene/TextureCache.h).
inline constexpr int kHardwareAnisotropy = 8;

// The choices, resolved: the profile's, with the overrides applied. The numbers behind each are
// in docs/performance.md.
struct DriverChoices {
    // Software or Gpu: the profile the choices are those of (Auto resolved on the context).
    DriverProfile profile = DriverProfile::Software;
    // Integer specular powers as chains of multiplications (SceneFeatures::specularExponents),
    // measured faster on llvmpipe; a GPU's pow() is two special-function instructions.
    bool multipliedSpecularPowers = true;
    // Passes that walk a batch of lights read the light texels where there are some, which
    // llvmpipe fetches faster; a GPU reads the batch's uniform window, a broadcast
    // (GpuScene::readsLightWindows).
    bool lightTexelsBeforeWindows = true;
    // The anisotropy --anisotropy auto gives (TextureCache): 1 where every tap costs CPU time,
    // kHardwareAnisotropy where the texture units filter nearly for free.
    int autoAnisotropy = 1;
    // How frames are timed: Wall on a software rasteriser, whose timer queries miss its threads'
    // work; on a GPU, timer queries and frames issued back to back, as an application issues
    // them (a glFinish would drain the GPU between passes).
    PassTiming passTiming = PassTiming::Wall;
    // deferred's and clustered's lighting stage. Compute on a GPU: how current deferred renderers
    // light, and on the compute GPUs lent to this project (H100, H200) the only way the lighting
    // gets the whole chip (2 of an H100's 66 texture processing clusters run fragment shaders).
    // On llvmpipe the fragment pass is the one measured faster (docs/techniques.md).
    LightingStage lightingStage = LightingStage::Fragment;
    // The light loops branch where a light does not reach the pixel (BRANCH_ON_REACH in the
    // shaders): a GPU's warp whose lanes are all out of reach skips the shading. llvmpipe runs
    // both sides of a branch under a mask, so there the loops test first and select
    // (docs/performance.md).
    bool branchOnLightReach = false;

    bool operator==(const DriverChoices&) const = default;
};

// The choices of `overrides`: its profile's, with each override set in place of the profile's
// choice. Auto takes the GPU's profile unless the current context's GL_RENDERER names a
// software rasteriser (gl::isSoftwareRenderer), and so needs a current context.
DriverChoices resolveDriverChoices(const DriverOverrides& overrides);

}  // namespace manylights
