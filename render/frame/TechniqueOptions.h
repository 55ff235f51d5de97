// How a technique's shaders are built (TechniqueOptions) and what a technique reports of a
// frame (TechniqueCounter): in frame/, below the rooms that build shaders for a technique
// (culling's lists, effects' transparency pass) as well as the techniques themselves.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "gl/Program.h"
#include "render/driver/DriverProfile.h"
#include "render/frame/GBuffer.h"

namespace manylights {

// The culling's tuning: settings for measuring and testing that change how the lights' lists
// are made, never the image (docs/cli.md, "Environment"). Each unset takes the
// measured default; the command layer reads them from the environment and checks them.
struct CullingTuning {
    // The share of the light grid's tiles a light's screen rectangle must cover to be global
    // (render/culling/ClusterLists.h, kGlobalLightGridFraction), a number > 0; above 1 only an
    // unbounded light is global.
    std::optional<double> globalLightGridFraction{};
    // The most lights whose lists are made from bit masks rather than sorted, up to
    // kMaskedListLights (render/culling/ClusterLists.h); 0: every frame sorts its pairs.
    std::optional<std::uint32_t> maskedListLights{};
    // The threads tiled-quads culls on at every light count, 1 to kMaxCullingThreads
    // (render/culling/TileCulling.h); unset: by the light count.
    std::optional<unsigned> cullingThreads{};

    bool operator==(const CullingTuning&) const = default;
};

// How a technique is made: its shaders' variant and its culling's tuning.
struct TechniqueOptions {
    // Shader variants that count the (pixel, light) pairs they evaluate into
    // FrameTargets::lightEvaluations (--count-work, --view light-count). Costs an atomic per
    // fragment, so timings taken with it are not the technique's own.
    bool countWork = false;
    // The G-buffer the technique's shaders read; must be the layout of the FrameTargets it
    // renders into (Renderer's).
    GBufferLayout gbufferLayout = kDefaultGBufferLayout;
    // Shader variants that look up local lights' shadow maps (LOCAL_SHADOWS). Needed when the
    // Renderer's ShadowMaps has a local-light budget above 0; without it those lights shade
    // unshadowed. A separate variant because on llvmpipe the lookup code costs every (pixel,
    // light) pair even when no light has a map (it runs masked, not skipped): 5x the deferred
    // lighting pass.
    bool localShadows = false;
    // deferred's and clustered's lighting stage (DriverChoices::lightingStage).
    LightingStage lightingStage = LightingStage::Fragment;
    CullingTuning culling{};

    bool operator==(const TechniqueOptions&) const = default;
};

// The shader #defines that realise `options`.
gl::Defines shaderDefines(const TechniqueOptions& options);

// A technique-specific figure of the last frame for --stats (e.g. tiles whose light list
// overflowed).
struct TechniqueCounter {
    std::string name;
    double value;
};

}  // namespace manylights
