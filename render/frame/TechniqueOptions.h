// How a technique is made (TechniqueOptions) and what a technique reports of a
// frame (TechniqueCounter): in frame/, below the rooms that build shaders for a technique
// (culling's lists, effects' transparency pass) as well as the techniques themselves.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "render/driver/DriverProfile.h"
#include "render/programs/LightingPrograms.h"

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

// How a technique is made: its shaders' variant, its lighting stage and its culling's tuning.
struct TechniqueOptions {
    // What all its programs are made for: whether they count work, the G-buffer they read,
    // whether they look up local lights' shadows (render/programs/LightingPrograms.h).
    TechniqueVariant shaders{};
    // deferred's and clustered's lighting stage (DriverChoices::lightingStage): which shader
    // files their lighting is compiled from, not a #define.
    LightingStage lightingStage = LightingStage::Fragment;
    CullingTuning culling{};

    bool operator==(const TechniqueOptions&) const = default;
};

// A technique-specific figure of the last frame for --stats (e.g. tiles whose light list
// overflowed).
struct TechniqueCounter {
    std::string name;
    double value;
};

}  // namespace manylights
