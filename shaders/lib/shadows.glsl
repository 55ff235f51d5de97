// Shadow and ambient-occlusion factors (docs/shadows.md). lib/lighting.glsl multiplies them
// into its terms, so every technique applies them the same way. render/effects/ShadowMaps.cpp (the directional
// light's map), render/shadows/ShadowPool.cpp (the local lights' pages) and
// render/effects/Ssao.cpp fill the maps; render/effects/ShadowMaps.h (ShadowingUniforms) has the same std140 layout for the block.
#include "lib/bindings.glsl"
layout(std140, binding = SHADOWING_BLOCK_BINDING) uniform Shadowing {
    mat4 directionalShadowMatrix;  // world position -> shadow-map uv (xy) and depth (z), all in [0, 1]
    vec4 directionalShadowParams;  // x: 1 when the directional light casts shadows; y: 1 / map size
    vec4 occlusionParams;          // x: 1 when ambient occlusion multiplies the ambient term
    vec4 localShadowParams;        // x: 1 when some local light casts shadows; y, z: 1 / the shadow
                                   // atlas' width, height; w: the page tables' first face texel
                                   // (lib/shadow_pages.glsl)
} shadowing;

#include "lib/shadow_pages.glsl"

// Depth comparison in hardware (GL_COMPARE_REF_TO_TEXTURE) with bilinear filtering: each
// tap is already a 2x2 percentage-closer filter.
layout(binding = DIRECTIONAL_SHADOW_UNIT) uniform sampler2DShadow directionalShadowMap;
// The blurred ambient-occlusion factor of each screen pixel (render/effects/Ssao.cpp).
layout(binding = AMBIENT_OCCLUSION_UNIT) uniform sampler2D ambientOcclusionMap;

// The fraction of the directional light that reaches `position` (1: lit, 0: in the umbra):
// a 3x3 percentage-closer filter over the shadow map. The depth bias is in the map itself
// (slope-scaled polygon offset when it is rendered), so a lit surface compares its own depth
// with a map value pushed slightly away from the light. Points outside the map are lit: the
// map covers every surface the camera can see (render/effects/ShadowMaps.cpp fits it).
float directionalShadow(vec3 position)
{
#ifdef NO_DIRECTIONAL_SHADOW  // a frame without the map (render/programs/LightingPrograms.h)
    return 1.0;
#endif
    if (shadowing.directionalShadowParams.x == 0.0)
        return 1.0;
    vec3 coord = (shadowing.directionalShadowMatrix * vec4(position, 1.0)).xyz;
    if (any(lessThan(coord, vec3(0.0))) || any(greaterThan(coord, vec3(1.0))))
        return 1.0;
    float texel = shadowing.directionalShadowParams.y;
    float lit = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            lit += texture(directionalShadowMap, vec3(coord.xy + vec2(dx, dy) * texel, coord.z));
    return lit / 9.0;
}

// The fraction of local light `light` (index `lightIndex`) that reaches `position`, a surface
// of normal `normal`: its shadow page's tap (lib/shadow_pages.glsl), 1 where it casts none.
float localShadow(uint lightIndex, GpuLight light, vec3 position, vec3 normal)
{
#ifndef LOCAL_SHADOWS
    // The variant without local shadows (TechniqueVariant::localShadows): llvmpipe would run
    // the lookup below under a lane mask for every (pixel, light) pair even when the uniform
    // says they are off.
    return 1.0;
#endif
    if (shadowing.localShadowParams.x == 0.0)
        return 1.0;
    return shadowPageLookup(lightIndex, light, position, normal, shadowing.localShadowParams.yz,
                            int(shadowing.localShadowParams.w));
}

#ifdef SHADOW_RESOLUTION_VIEW
// What --view shadow-resolution adds up for a pair in reach (TechniqueVariant::
// showShadowResolution, docs/shadows.md): x the log2 of the texels per pixel of the page the
// lookup of local light `light` reads at `position`, y 1, so that the walk's sum over a pixel's
// pairs holds the sum of the logs and their count (the view shows 2^(x / y), their geometric
// mean); nothing where the light has no page there, or no light has any.
vec3 shadowResolutionTerm(uint lightIndex, GpuLight light, vec3 position)
{
    if (shadowing.localShadowParams.x == 0.0)
        return vec3(0.0);
    float texelsPerPixel = shadowPageTexelsPerPixel(lightIndex, light, position, int(shadowing.localShadowParams.w));
    return texelsPerPixel > 0.0 ? vec3(log2(texelsPerPixel), 1.0, 0.0) : vec3(0.0);
}
#endif

// The screen pixel a world position falls in. Every technique computes it from the same
// position, so forward (which has gl_FragCoord) and compute shaders (which do not) read the
// same texel.
ivec2 screenPixel(vec3 position)
{
    vec4 clip = frame.viewProjection * vec4(position, 1.0);
    vec2 ndc = clip.xy / clip.w;
    return clamp(ivec2(floor((ndc * 0.5 + 0.5) * frame.viewport.xy)), ivec2(0), ivec2(frame.viewport.xy) - 1);
}

// The ambient-occlusion factor (1: open, 0: fully occluded) at a visible surface point.
float ambientOcclusion(vec3 position)
{
// A surface the occlusion map was not made from (a transparent one), or a frame without it.
#ifdef NO_AMBIENT_OCCLUSION
    return 1.0;
#endif
    if (shadowing.occlusionParams.x == 0.0)
        return 1.0;
    return texelFetch(ambientOcclusionMap, screenPixel(position), 0).r;
}
