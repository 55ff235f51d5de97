// The lights a pass loops over: one batch of the light buffer (render/programs/LightBatches.h says
// why: llvmpipe silently ends a shader's loops after 65,535 iterations in all, so no pass
// may loop over every light of a large scene). The renderer draws the pass once per batch,
// adding to the lit image; the first batch also adds the light-independent terms.
#include "lib/locations.glsl"
layout(location = LIGHT_BATCH_LOCATION) uniform uvec2 lightBatch;  // first light, one past the last

bool isFirstLightBatch()
{
    return lightBatch.x == 0u;
}

// The words of a bit mask over the batch's lights (bit i: light lightBatch.x + i), as the
// transparency grid's clusters and the in-range count keep them, and of its
// summary (bit w % 32 of word w / 32: mask word w is not empty).
uint lightBatchMaskWords()
{
    return (lightBatch.y - lightBatch.x + 31u) / 32u;
}

uint lightBatchSummaryWords()
{
    return (lightBatchMaskWords() + 31u) / 32u;
}
