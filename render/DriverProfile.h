// The choices the renderer makes by the kind of driver it runs on (issue 30): what was measured
// fastest on a software rasteriser (Mesa's llvmpipe) and what the vendors advise on a GPU.
// --driver-profile (docs/cli.md) picks them by name, so that the GPU's code paths are tested on
// llvmpipe and the other way round; `auto` picks them by GL_RENDERER.
//
// driverChoices() is the one place that decides from the profile: code that behaves
// differently on a GPU reads a field of DriverChoices, never the driver's name.
#pragma once

#include <optional>
#include <string_view>

namespace manylights {

enum class DriverProfile { Auto, Software, Gpu };

std::string_view driverProfileName(DriverProfile profile);  // "auto", "software" or "gpu"
std::optional<DriverProfile> parseDriverProfile(std::string_view name);

// The profile's choices. The numbers behind each are in docs/performance.md.
struct DriverChoices {
    // Software or Gpu: the profile the choices are those of (Auto resolved on the context).
    DriverProfile profile = DriverProfile::Software;
    // Integer specular powers as chains of multiplications (LightingFeatures::specularExponents),
    // measured faster on llvmpipe; a GPU's pow() is two special-function instructions.
    bool multipliedSpecularPowers = true;
    // Passes that walk a batch of lights read the light texels where there are some, which
    // llvmpipe fetches faster; a GPU reads the batch's uniform window, a broadcast
    // (GpuScene::readsLightWindows).
    bool lightTexelsBeforeWindows = true;
    // The anisotropy --anisotropy auto gives (TextureCache): 1 where every tap costs CPU time,
    // kHardwareAnisotropy where the texture units filter nearly for free.
    int autoAnisotropy = 1;
    // How frames are timed (render/frame/PassProfiler.h): a glFinish around every pass, whose
    // wall clock is exact on a software rasteriser (its timer queries miss its threads' work),
    // or, on a GPU, timer queries and frames issued back to back, as an application issues
    // them (a glFinish would drain the GPU between passes).
    bool finishAroundPasses = true;
    // deferred's and clustered's lighting as a compute pass rather than a full-screen fragment
    // pass (LightingStage): how current deferred renderers light on a GPU, and on the compute
    // GPUs lent to this project (H100, H200) the only way the lighting gets the whole chip (2
    // of an H100's 66 texture processing clusters run fragment shaders). On llvmpipe the
    // fragment pass is the one measured (docs/techniques.md).
    bool computeLighting = false;
    // The light loops branch where a light does not reach the pixel (BRANCH_ON_REACH in the
    // shaders): a GPU's warp whose lanes are all out of reach skips the shading. llvmpipe runs
    // both sides of a branch under a mask, so there the loops test first and select
    // (docs/performance.md).
    bool branchOnLightReach = false;
};

// The choices of `profile`; Auto takes the GPU's unless the current context's GL_RENDERER
// names a software rasteriser (gl::isSoftwareRenderer), and needs a current context.
DriverChoices driverChoices(DriverProfile profile);

}  // namespace manylights
