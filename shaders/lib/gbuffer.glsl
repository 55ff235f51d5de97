// Reading the G-buffer back into a Surface, texel for texel (no filtering).
layout(binding = 0) uniform sampler2D gPositionShininess;
layout(binding = 1) uniform sampler2D gNormal;
layout(binding = 2) uniform sampler2D gDiffuse;
layout(binding = 3) uniform sampler2D gSpecular;
layout(binding = 4) uniform sampler2D gEmissive;

Surface gbufferSurface(ivec2 pixel)
{
    vec4 positionShininess = texelFetch(gPositionShininess, pixel, 0);
    Surface s;
    s.position = positionShininess.xyz;
    s.normal = texelFetch(gNormal, pixel, 0).xyz;
    s.diffuse = texelFetch(gDiffuse, pixel, 0).rgb;
    s.specular = texelFetch(gSpecular, pixel, 0).rgb;
    s.shininess = positionShininess.w;
    s.emissive = texelFetch(gEmissive, pixel, 0).rgb;
    return s;
}
