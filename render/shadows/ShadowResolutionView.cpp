#include "render/shadows/ShadowResolutionView.h"

#include "core/Error.h"

namespace manylights {

namespace {
// Attempts where the lists did not hold the frame's pairs (ClusterLists plans anew for the
// next; the second holds them), as the shadow pool's marking.
constexpr int kAttempts = 3;
}  // namespace

ShadowResolutionView::ShadowResolutionView() = default;
ShadowResolutionView::~ShadowResolutionView() = default;

void ShadowResolutionView::draw(const GpuScene& scene, FrameTargets& targets, FramePasses& passes,
                                const TechniqueOptions& options)
{
    // The walk of the lists as the lighting's, adding the figure up instead of light.
    TechniqueOptions wanted = options;
    wanted.shaders.countWork = false;
    wanted.shaders.localShadows = false;
    wanted.shaders.markShadowPages = false;
    wanted.shaders.showShadowResolution = true;
    wanted.lightingStage = LightingStage::Compute;
    if (!madeFor_ || *madeFor_ != wanted) {
        grid_ = std::make_unique<ClusterGrid>(wanted.shaders.gbufferLayout, kClusteredGridShape);
        lists_ = std::make_unique<ClusterLists>(kClusteredGridShape, wanted.culling);
        walk_ = std::make_unique<ListLighting>("shadow resolution view", wanted, kClusteredGridShape,
                                               LightingStage::Compute);
        madeFor_ = wanted;
    }
    for (int attempt = 1;; ++attempt) {
        buildListsOverSurfaces(scene, targets, passes, *grid_, *lists_);
        walk_->run(scene, *grid_, *lists_, passes);
        lists_->frameIssued();
        if (lists_->oldestFrameFitted())
            return;
        if (attempt == kAttempts)
            throw Error("the shadow-resolution view's light lists cannot hold this frame's pairs");
    }
}

}  // namespace manylights
