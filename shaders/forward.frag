#version 450 core
// forward: every fragment of every object loops over all lights (one batch of them per
// draw of the objects: lib/light_batch.glsl). The reference image.
#include "lib/lighting.glsl"
#include "lib/light_batch.glsl"
#include "lib/material.glsl"

layout(location = 0) out vec4 outColor;

void main()
{
    Surface s = meshSurface();
    vec3 V = viewVector(s.position);
    vec3 color = isFirstLightBatch() ? shadeGlobal(s, V) : vec3(0.0);
    for (uint i = lightBatch.x; i < lightBatch.y; ++i)
        color += shadeLocal(i, s, V);
    recordLightEvaluations(lightBatch.y - lightBatch.x);
    outColor = vec4(color, 1.0);
}
