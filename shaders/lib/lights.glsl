// The local lights, all of them in one storage buffer (render/scene/SceneLights.cpp packs it).
#include "lib/bindings.glsl"
struct GpuLight {
    vec4 positionRadius;     // xyz: position; w: culling radius (UNBOUNDED_RADIUS when none)
    vec4 intensityExponent;  // rgb: intensity; w: spot exponent (0 for point lights)
    vec4 attenuation;        // classic: (c, b, a, 0); range falloff: (r, 0, 0, 1)
    vec4 spotAxisCosCutoff;  // xyz: unit spot axis; w: cos(cutoff). Point lights: w = -2, so
                             // every direction is inside the "cone" and S = 1.
};

layout(std430, binding = LIGHTS_BUFFER_BINDING) readonly buffer Lights {
    GpuLight lights[];
};

// A light kept as four RGBA32F texels from `first` of `texels` (the light texels; the global
// list's records, lib/cluster_lists.glsl), its first texel, positionRadius, fetched already.
GpuLight lightFromTexels(samplerBuffer texels, int first, vec4 positionRadius)
{
    GpuLight light;
    light.positionRadius = positionRadius;
    light.intensityExponent = texelFetch(texels, first + 1);
    light.attenuation = texelFetch(texels, first + 2);
    light.spotAxisCosCutoff = texelFetch(texels, first + 3);
    return light;
}

#ifdef LIGHT_WINDOW_BINDING
// The batch's lights as a uniform block bound to their range of the same buffer
// (render/programs/LightBatches.h: light windows), for passes where every pixel walks the batch in
// order; light i of the scene is element i − lightBatch.x. Such a shader includes
// lib/light_batch.glsl before this file (an #include here would count as done even where this
// block is compiled out, and leave other shaders without it).
layout(std140, binding = LIGHT_WINDOW_BLOCK_BINDING) uniform LightWindow {
    GpuLight windowLights[LIGHTS_PER_WINDOW];
};

GpuLight batchLight(uint lightIndex)
{
    return windowLights[lightIndex - lightBatch.x];
}

vec4 lightPositionRadius(uint lightIndex)
{
    return windowLights[lightIndex - lightBatch.x].positionRadius;
}

GpuLight lightWithPositionRadius(uint lightIndex, vec4 positionRadius)
{
    return windowLights[lightIndex - lightBatch.x];
}
#elif defined(LIGHT_TEXELS)
// The same buffer as four RGBA32F texels per light (render/programs/LightBatches.h: light texels), for
// passes whose pixels read different lights, and for every pass on a software rasteriser:
// llvmpipe fetches a texel for all lanes at once, loads from a storage buffer lane by lane
// and gathers from a uniform block per component.
layout(binding = LIGHT_TEXELS_UNIT) uniform samplerBuffer lightTexels;

GpuLight batchLight(uint lightIndex)
{
    int first = int(lightIndex) * 4;
    return lightFromTexels(lightTexels, first, texelFetch(lightTexels, first));
}

vec4 lightPositionRadius(uint lightIndex)
{
    return texelFetch(lightTexels, int(lightIndex) * 4);
}

// The rest of the light whose first texel was fetched already (lightPositionRadius).
GpuLight lightWithPositionRadius(uint lightIndex, vec4 positionRadius)
{
    return lightFromTexels(lightTexels, int(lightIndex) * 4, positionRadius);
}
#else
GpuLight batchLight(uint lightIndex)
{
    return lights[lightIndex];
}

vec4 lightPositionRadius(uint lightIndex)
{
    return lights[lightIndex].positionRadius;
}

GpuLight lightWithPositionRadius(uint lightIndex, vec4 positionRadius)
{
    GpuLight light = lights[lightIndex];
    light.positionRadius = positionRadius;
    return light;
}
#endif
