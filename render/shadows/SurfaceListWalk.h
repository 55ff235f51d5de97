// A walk of clustered's light lists over the frame's visible surfaces (the G-buffer) that does
// not depend on the technique rendering the frame: its own grid and lists, and the lists'
// lighting (render/techniques/ListLighting.h) in the variant its options ask for. The shadow
// pool's marking (TechniqueVariant::markShadowPages) and --view shadow-resolution
// (showShadowResolution) walk the pairs the lighting shades with it, so that every technique
// reads what they found.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "render/culling/ClusterGrid.h"
#include "render/culling/ClusterLists.h"
#include "render/frame/FramePasses.h"
#include "render/frame/FrameTargets.h"
#include "render/frame/TechniqueOptions.h"
#include "render/scene/GpuScene.h"
#include "render/techniques/ListLighting.h"

namespace manylights {

class SurfaceListWalk {
public:
    // Made for `options` (their lighting stage is compute whatever they say); `label` names its
    // programs and the error below.
    SurfaceListWalk(std::string label, const TechniqueOptions& options);
    // Whether it was made for `options` (as the constructor takes them).
    bool madeFor(const TechniqueOptions& options) const;

    // Builds the lists over the frame's surfaces and walks them (a pass that writes
    // `alsoWrites` besides the lit image). Where the lists did not hold the frame's pairs,
    // they are planned anew and the walk made again, `beforeEachWalk` first each time (to
    // reset what the walk adds to); a third failure throws manylights::Error.
    void run(const GpuScene& scene, FrameTargets& targets, FramePasses& passes, Resource alsoWrites,
             const std::function<void()>& beforeEachWalk = {});

private:
    std::string label_;
    TechniqueOptions options_;
    ClusterGrid grid_;
    ClusterLists lists_;
    ListLighting walk_;
};

}  // namespace manylights
