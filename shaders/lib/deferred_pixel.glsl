// deferred's lighting of one pixel, which deferred.frag and deferred.comp wrap
// (lib/lighting_stage.glsl): the batch's lights (lib/light_batch.glsl), every one of them, and
// in the first batch the light-independent terms. Loop iterations: one batch
// (render/programs/LightBatches.h).
vec3 shadeDeferredPixel(ivec2 pixel)
{
    Surface s = gbufferSurface(pixel);
    vec3 V = viewVector(s.position);
    vec3 color = isFirstLightBatch() ? shadeGlobal(s, V) : vec3(0.0);
    for (uint i = lightBatch.x; i < lightBatch.y; ++i)
        color += shadeLocal(i, s, V);
    recordLightEvaluationsAt(pixel, lightBatch.y - lightBatch.x);
    return color;
}
