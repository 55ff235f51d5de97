#version 450 core
// deferred's lighting as a compute pass (--lighting-stage compute, the GPU profile's choice,
// docs/techniques.md): an invocation per pixel, one dispatch per light batch
// (lib/light_batch.glsl), each covered pixel looping over all the batch's lights as
// deferred.frag does. The first batch stores the global terms and its lights' sum, later ones
// add theirs to what is stored, the sum the fragment pass's additive blending makes: the same
// image, bit for bit. Loop iterations: one batch (render/culling/LightBatches.h).
#include "lib/bindings.glsl"
#define LIGHTING_IN_COMPUTE 1
// lib/light_batch.glsl first: lib/lights.glsl's light window needs it.
#include "lib/light_batch.glsl"
#include "lib/lighting.glsl"
#include "lib/gbuffer.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = SCENE_DEPTH_UNIT) uniform sampler2D sceneDepth;
layout(binding = LIT_IMAGE_UNIT, rgba32f) uniform image2D litImage;

void main()
{
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, imageSize(litImage))) || texelFetch(sceneDepth, pixel, 0).r >= 1.0)
        return;
    Surface s = gbufferSurface(pixel);
    vec3 V = viewVector(s.position);
    vec3 color = isFirstLightBatch() ? shadeGlobal(s, V) : vec3(0.0);
    for (uint i = lightBatch.x; i < lightBatch.y; ++i)
        color += shadeLocal(i, s, V);
    recordLightEvaluationsAt(pixel, lightBatch.y - lightBatch.x);
    // As the blend unit adds the fragment pass's colour to the stored one.
    if (!isFirstLightBatch())
        color = color + imageLoad(litImage, pixel).rgb;
    imageStore(litImage, pixel, vec4(color, 1.0));
}
