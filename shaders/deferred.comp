#version 450 core
// deferred's lighting as a compute pass (--lighting-stage compute, the GPU profile's choice,
// docs/techniques.md): an invocation per pixel, one dispatch per light batch
// (lib/light_batch.glsl), each covered pixel lit by lib/deferred_pixel.glsl as in deferred.frag.
// The first batch stores, later ones add to what is stored (lib/lighting_stage.glsl).
#include "lib/bindings.glsl"
#define LIGHTING_IN_COMPUTE 1
// lib/light_batch.glsl first: lib/lights.glsl's light window needs it.
#include "lib/light_batch.glsl"
#include "lib/lighting.glsl"
#include "lib/gbuffer.glsl"
#include "lib/lighting_stage.glsl"
#include "lib/deferred_pixel.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

void main()
{
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (isLitPixel(pixel))
        storeLitPixel(pixel, shadeDeferredPixel(pixel), !isFirstLightBatch());
}
