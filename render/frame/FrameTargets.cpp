#include "render/frame/FrameTargets.h"

namespace manylights {

FrameTargets::FrameTargets(int width_, int height_, GBufferLayout gbufferLayout)
    : width(width_),
      height(height_),
      depthStencil("depth stencil", kDepthStencilTarget.format, width_, height_),
      lit("lit colour", GL_RGBA32F, width_, height_),
      litFramebuffer("lit", {&lit}, &depthStencil),
      gbuffer(width_, height_, depthStencil, gbufferLayout),
      lightEvaluations("light evaluations", GL_R32UI, width_, height_),
      inRangeCounts("in-range lights", GL_R32UI, width_, height_)
{
}

}  // namespace manylights
