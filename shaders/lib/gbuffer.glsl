// Reading the G-buffer back into a Surface, texel for texel (no filtering), in the layout
// chosen by GBUFFER_COMPACT (render/GBuffer.h gives both; docs/gbuffer.md their precision).
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
#ifdef GBUFFER_COMPACT
    // One texel fetch for the whole surface: llvmpipe's cost per fetch, not per byte, is what
    // a light volume's fragment pays for every (pixel, light) pair (docs/gbuffer.md).
    uvec4 stored = texelFetch(gSurface, pixel, 0);
    s.position = gbufferPositionAtDepth(pixel, surfaceViewDepth(stored));
    s.normal = surfaceNormal(stored);
    s.diffuse = surfaceDiffuse(stored);
    s.specular = surfaceSpecular(stored);
    s.shininess = surfaceShininess(stored);
#else
    s.position = gbufferPosition(pixel);
    s.normal = texelFetch(gNormal, pixel, 0).xyz;
    s.diffuse = texelFetch(gDiffuse, pixel, 0).rgb;
    s.specular = texelFetch(gSpecular, pixel, 0).rgb;
    s.shininess = texelFetch(gPositionShininess, pixel, 0).w;
#endif
    s.emissive = texelFetch(gEmissive, pixel, 0).rgb;
    return withTermSwitches(s);
}
