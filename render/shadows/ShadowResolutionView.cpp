#include "render/shadows/ShadowResolutionView.h"

namespace manylights {

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
    if (!walk_ || !walk_->madeFor(wanted))
        walk_ = std::make_unique<SurfaceListWalk>("shadow resolution view", wanted);
    walk_->run(scene, targets, passes, Resource::None);
}

}  // namespace manylights
