// A lighting technique: how the lit image of a frame is made. Techniques differ only in
// which (pixel, light) pairs they visit; all of them shade with shaders/lib/lighting.glsl.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "render/driver/DriverProfile.h"
#include "render/frame/FrameTargets.h"
#include "render/frame/GBuffer.h"

namespace manylights {

class GpuScene;
class FramePasses;

// How a technique's shaders are built.
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
    LightingStage lightingStage = LightingStage::Fragment;

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

class Technique {
public:
    explicit Technique(const TechniqueOptions& options) : options_(options) {}
    virtual ~Technique() = default;
    virtual std::string_view name() const = 0;
    // What the technique's shaders were made for; the passes the renderer adds to every
    // technique's frame (render/effects/TransparencyPass.h) are made for the same.
    const TechniqueOptions& options() const { return options_; }
    // The reference (forward): passes shared by every technique then loop over every light
    // instead of culling them, so that the reference stays free of culling.
    virtual bool isReference() const { return false; }
    virtual std::vector<TechniqueCounter> counters() const { return {}; }
    // Renders the frame into targets.lit (already cleared to the background colour) and
    // leaves the scene's depth in targets.depthStencil.
    virtual void render(const GpuScene& scene, FrameTargets& targets, FramePasses& passes) = 0;
    // After all of a frame's commands are issued (the technique's and the passes after it): a
    // technique whose storage is planned ahead keeps what it must check of the frame once the
    // GPU has run it (render/culling/ClusterLists.h).
    virtual void frameIssued() {}
    // Of the oldest frame issued and not yet checked, waiting for the GPU to finish it where it
    // has not: false when the storage the technique planned for it (from a frame before) could
    // not hold the frame's work, in which case the technique has planned for it and the
    // renderer renders the frame again.
    virtual bool oldestFrameFitted() { return true; }

private:
    TechniqueOptions options_;
};

// The techniques docs/cli.md names, in the order of the docs.
const std::vector<std::string>& techniqueNames();
// nullptr when the name is unknown.
std::unique_ptr<Technique> makeTechnique(std::string_view name, const TechniqueOptions& options = {});
// Which lights the technique's light-count view counts at a pixel, in a few words ("every
// light", "cluster's lights in reach"); empty when the name is unknown.
std::string_view countedLights(std::string_view technique);

}  // namespace manylights
