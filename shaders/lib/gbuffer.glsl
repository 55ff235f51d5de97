// Reading the G-buffer back into a Surface, texel for texel (no filtering), in the layout
// chosen by GBUFFER_COMPACT (render/GBuffer.h gives both; docs/gbuffer.md their precision).
// gbufferSurface() is THE way to read a surface from the G-buffer.
#include "lib/bindings.glsl"
#include "lib/gbuffer_position.glsl"
#include "lib/gbuffer_packing.glsl"

layout(binding = GBUFFER_NORMAL_UNIT) uniform sampler2D gNormal;
layout(binding = GBUFFER_DIFFUSE_UNIT) uniform sampler2D gDiffuse;
layout(binding = GBUFFER_SPECULAR_UNIT) uniform sampler2D gSpecular;
layout(binding = GBUFFER_EMISSIVE_UNIT) uniform sampler2D gEmissive;

Surface gbufferSurface(ivec2 pixel)
{
    Surface s;
    s.position = gbufferPosition(pixel);
#ifdef GBUFFER_COMPACT
    vec4 diffuseShininessHigh = texelFetch(gDiffuse, pixel, 0);
    vec4 specularShininessLow = texelFetch(gSpecular, pixel, 0);
    s.normal = octahedralDecode(texelFetch(gNormal, pixel, 0).xy);
    s.diffuse = diffuseShininessHigh.rgb;
    s.specular = specularShininessLow.rgb;
    s.shininess = decodeShininess(diffuseShininessHigh.a, specularShininessLow.a);
#else
    s.normal = texelFetch(gNormal, pixel, 0).xyz;
    s.diffuse = texelFetch(gDiffuse, pixel, 0).rgb;
    s.specular = texelFetch(gSpecular, pixel, 0).rgb;
    s.shininess = texelFetch(gPositionShininess, pixel, 0).w;
#endif
    s.emissive = texelFetch(gEmissive, pixel, 0).rgb;
    return withTermSwitches(s);
}
