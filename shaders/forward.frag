#version 450 core
// forward: every fragment of every object loops over all lights. The reference image.
#include "lib/lighting.glsl"
#include "lib/material.glsl"

layout(location = 0) out vec4 outColor;

void main()
{
    Surface s = meshSurface();
    vec3 V = viewVector(s.position);
    vec3 color = shadeGlobal(s, V);
    for (uint i = 0u; i < frame.counts.x; ++i)
        color += shadeLocal(i, s, V);
    recordLightEvaluations(frame.counts.x);
    outColor = vec4(color, 1.0);
}
