#version 450 core
// deferred: one full-screen pass per light batch (lib/light_batch.glsl), each covered pixel
// loops over all the batch's lights.
// lib/light_batch.glsl first: lib/lights.glsl's light window needs it.
#include "lib/light_batch.glsl"
#include "lib/lighting.glsl"
#include "lib/gbuffer.glsl"

layout(early_fragment_tests) in;
layout(location = 0) out vec4 outColor;

void main()
{
    Surface s = gbufferSurface(ivec2(gl_FragCoord.xy));
    vec3 V = viewVector(s.position);
    vec3 color = isFirstLightBatch() ? shadeGlobal(s, V) : vec3(0.0);
    for (uint i = lightBatch.x; i < lightBatch.y; ++i)
        color += shadeLocal(i, s, V);
    recordLightEvaluations(lightBatch.y - lightBatch.x);
    outColor = vec4(color, 1.0);
}
