#version 450 core
// The transparency pass (render/effects/TransparencyPass.h): a transparent surface (AlphaMode::Blend)
// shaded by the one lighting function, with the lights of its cluster in the grid that spans
// the transparent objects' depths (lib/cluster_lights.glsl), or under EVERY_LIGHT every light
// of the batch (what forward, the reference, does). Drawn "over" the lit image with
// premultiplied alpha (blend ONE, ONE_MINUS_SRC_ALPHA): the first light batch writes
// (coverage · colour, coverage), each later one adds coverage · its lights' colour with alpha
// 0. The ambient term has no occlusion: SSAO is made from the opaque surfaces' G-buffer.
#include "lib/bindings.glsl"
#ifndef NO_AMBIENT_OCCLUSION
#define NO_AMBIENT_OCCLUSION 1
#endif
// lib/light_batch.glsl first: lib/lights.glsl's light window needs it.
#include "lib/light_batch.glsl"
#include "lib/lighting.glsl"
#include "lib/material.glsl"
#ifndef EVERY_LIGHT
#include "lib/clusters.glsl"
#include "lib/cluster_lights.glsl"
#endif

layout(location = 0) out vec4 outColor;
#ifdef COUNT_WORK
// The pass's (pixel, light) pairs, apart from the opaque ones (stats: transparent_light_evaluations).
layout(std430, binding = TRANSPARENT_EVALUATIONS_BUFFER_BINDING) buffer TransparentEvaluations {
    uint transparentLightEvaluations;
};
#endif

void main()
{
    Surface s = meshSurface();
    vec3 V = viewVector(s.position);
    vec3 color = isFirstLightBatch() ? shadeGlobal(s, V) : vec3(0.0);
    uint evaluated = 0u;
#ifdef EVERY_LIGHT
    for (uint i = lightBatch.x; i < lightBatch.y; ++i)
        color += shadeLocal(i, s, V);
    evaluated = lightBatch.y - lightBatch.x;
#else
    uint tile = clusterTileOfPixel(uvec2(gl_FragCoord.xy));
    uint cluster = tile * uint(CLUSTER_SLICES) + sliceOfDepth(viewDepth(s.position), tileDepthRange[tile]);
    color += shadeClusterLights(cluster, s, V, evaluated);
#endif
    recordLightEvaluations(evaluated);
#ifdef COUNT_WORK
    atomicAdd(transparentLightEvaluations, evaluated);
#endif
    outColor = vec4(color * meshCoverage, isFirstLightBatch() ? meshCoverage : 0.0);
}
