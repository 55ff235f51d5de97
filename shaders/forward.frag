#version 450 core
// forward: every visible fragment of every object loops over all lights (one batch of them
// per draw of the objects: lib/light_batch.glsl). The reference image.
// lib/light_batch.glsl first: lib/lights.glsl's light window needs it.
#include "lib/light_batch.glsl"
#include "lib/lighting.glsl"
#include "lib/material.glsl"

#ifdef DEPTH_PREPASS
// The depth pre-pass (render/techniques/ForwardTechnique.cpp): depth only, so the lighting runs once per
// pixel. meshSurface() is called for the fragments it discards (an alpha mask's cut); the
// compiler drops the rest of it, since nothing reads the surface.
void main()
{
    meshSurface();
}
#else
// The depth and stencil tests before the shader even where it has side effects (--count-work's
// atomics), so that hidden fragments run nothing. Not for an alpha mask (bit 5): a cut fragment
// that ties at the pixel's depth would pass the stencil test before its discard, and keep the
// surface the pre-pass left there from being shaded.
#if (MATERIAL_VARIANT & 32) == 0
layout(early_fragment_tests) in;
#endif
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
#endif
