#version 450 core
// deferred: one full-screen pass per light batch (lib/light_batch.glsl), each covered pixel
// lit by lib/deferred_pixel.glsl; the blend unit adds the later batches.
// lib/light_batch.glsl first: lib/lights.glsl's light window needs it.
#include "lib/light_batch.glsl"
#include "lib/lighting.glsl"
#include "lib/gbuffer.glsl"
#include "lib/lighting_stage.glsl"
#include "lib/deferred_pixel.glsl"

void main()
{
    outColor = vec4(shadeDeferredPixel(ivec2(gl_FragCoord.xy)), 1.0);
}
