#include "render/frame/ScreenPasses.h"

namespace manylights {

void drawCoveredPixels(const gl::Program& program)
{
    program.use();
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

Pass lightBatchPass(const LightBatch& batch, Resource storage)
{
    return {.name = "lighting",
            .target = Resource::LitImage,
            .state = batch.isFirst() ? kCoveredPixels : kAddToCoveredPixels,
            .sampled = Resource::GBuffer,
            .storage = storage};
}

Pass computeLightingPass(const Pass& fragment)
{
    return {.name = fragment.name,
            .sampled = fragment.sampled,
            .images = Resource::LitImage,
            .storage = fragment.storage,
            .writes = fragment.writes | Resource::LitImage};
}

}  // namespace manylights
