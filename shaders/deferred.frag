#version 450 core
// deferred: one full-screen pass, each covered pixel loops over all lights.
#include "lib/lighting.glsl"
#include "lib/gbuffer.glsl"

layout(early_fragment_tests) in;
layout(location = 0) out vec4 outColor;

void main()
{
    Surface s = gbufferSurface(ivec2(gl_FragCoord.xy));
    vec3 V = viewVector(s.position);
    vec3 color = shadeGlobal(s, V);
    for (uint i = 0u; i < frame.counts.x; ++i)
        color += shadeLocal(i, s, V);
    recordLightEvaluations(frame.counts.x);
    outColor = vec4(color, 1.0);
}
