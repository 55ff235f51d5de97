// A lighting technique: how the lit image of a frame is made. Techniques differ only in
// which (pixel, light) pairs they visit; all of them shade with shaders/lib/lighting.glsl.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "render/frame/FrameTargets.h"
#include "render/frame/TechniqueOptions.h"

namespace manylights {

class GpuScene;
class FramePasses;

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

}  // namespace manylights
