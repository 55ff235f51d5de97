// Reading the G-buffer back into a Surface, texel for texel (no filtering), in the layout
// chosen by GBUFFER_COMPACT (render/frame/GBuffer.h gives both; docs/gbuffer.md their precision).
// gbufferSurface() is THE way to read a surface from the G-buffer.
#include "lib/bindings.glsl"
#include "lib/gbuffer_position.glsl"
#include "lib/gbuffer_packing.glsl"

#ifndef GBUFFER_COMPACT
layout(binding = GBUFFER_NORMAL_UNIT) uniform sampler2D gNormal;
layout(binding = GBUFFER_DIFFUSE_UNIT) uniform sampler2D gDiffuse;
layout(binding = GBUFFER_SPECULAR_UNIT) uniform sampler2D gSpecular;
#endif
layout(binding = GBUFFER_EMISSIVE_UNIT) uniform sampler2D gEmissive;

Surface gbufferSurface(ivec2 pixel)
{
    Surface s;
    vec4 emissive = texelFetch(gEmissive, pixel, 0);
    // The model from the emissive alpha (lib/gbuffer_packing.glsl packModelOcclusion), unless the
    // program is built for one model only (lib/lighting.glsl BY_MODEL).
    s.metallicRoughness = BY_MODEL(emissive.a < 0.0, true, false);
    s.occlusion = s.metallicRoughness ? -1.0 - emissive.a : 1.0;
    s.metallic = 0.0;
#ifdef GBUFFER_COMPACT
    // One texel fetch for the whole surface: llvmpipe's cost per fetch, not per byte, is what
    // a light volume's fragment pays for every (pixel, light) pair (docs/gbuffer.md).
    uvec4 stored = texelFetch(gSurface, pixel, 0);
    s.position = gbufferPositionAtDepth(pixel, surfaceViewDepth(stored));
    s.normal = surfaceNormal(stored);
    s.diffuse = surfaceDiffuse(stored);
    s.specular = surfaceSpecular(stored);
    s.shininess = surfaceShininess(stored);
    s.roughness = surfaceRoughness(stored);
    if (s.metallicRoughness) {
        vec3 baseColour = surfaceBaseColour(stored);
        s.metallic = surfaceMetallic(stored);
        s.diffuse = baseColour * (1.0 - s.metallic);
        s.specular = mix(vec3(0.04), baseColour, s.metallic);
    }
#else
    s.position = gbufferPosition(pixel);
    s.normal = texelFetch(gNormal, pixel, 0).xyz;
    s.diffuse = texelFetch(gDiffuse, pixel, 0).rgb;
    s.specular = texelFetch(gSpecular, pixel, 0).rgb;
    s.shininess = texelFetch(gPositionShininess, pixel, 0).w;
    s.roughness = s.shininess;
#endif
    s.emissive = emissive.rgb;
    return withTermSwitches(s);
}
