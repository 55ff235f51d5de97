#include "render/shadows/SurfaceListWalk.h"

#include "core/Error.h"

namespace manylights {

namespace {

// Walks where the lists did not hold the frame's pairs (ClusterLists plans anew for the next;
// the second holds them unless the lights moved in between).
constexpr int kAttempts = 3;

TechniqueOptions inCompute(TechniqueOptions options)
{
    options.lightingStage = LightingStage::Compute;
    return options;
}

}  // namespace

SurfaceListWalk::SurfaceListWalk(std::string label, const TechniqueOptions& options)
    : label_(std::move(label)),
      options_(inCompute(options)),
      grid_(options_.shaders.gbufferLayout, kClusteredGridShape),
      lists_(kClusteredGridShape, options_.culling),
      walk_(label_, options_, kClusteredGridShape, LightingStage::Compute)
{
}

bool SurfaceListWalk::madeFor(const TechniqueOptions& options) const { return options_ == inCompute(options); }

void SurfaceListWalk::run(const GpuScene& scene, FrameTargets& targets, FramePasses& passes, Resource alsoWrites,
                          const std::function<void()>& beforeEachWalk)
{
    for (int attempt = 1;; ++attempt) {
        if (beforeEachWalk)
            beforeEachWalk();
        buildListsOverSurfaces(scene, targets, passes, grid_, lists_);
        walk_.run(scene, grid_, lists_, passes, alsoWrites);
        lists_.frameIssued();
        if (lists_.oldestFrameFitted())
            return;
        if (attempt == kAttempts)
            throw Error("the " + label_ + "'s light lists cannot hold this frame's pairs");
    }
}

}  // namespace manylights
