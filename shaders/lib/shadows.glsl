// Shadow and ambient-occlusion factors (docs/shadows.md). lib/lighting.glsl multiplies them
// into its terms, so every technique applies them the same way. render/effects/ShadowMaps.cpp and
// render/effects/Ssao.cpp fill the maps; render/effects/ShadowMaps.h (ShadowingUniforms) has the same std140 layout for the block.
#include "lib/bindings.glsl"
layout(std140, binding = SHADOWING_BLOCK_BINDING) uniform Shadowing {
    mat4 directionalShadowMatrix;  // world position -> shadow-map uv (xy) and depth (z), all in [0, 1]
    vec4 directionalShadowParams;  // x: 1 when the directional light casts shadows; y: 1 / map size
    vec4 occlusionParams;          // x: 1 when ambient occlusion multiplies the ambient term
    vec4 localShadowParams;        // x: 1 when some local light casts shadows; y: 1 / spot map size;
                                   // z: 1 / cube face size
} shadowing;

// Local lights' shadows: which slot each light has (−1: none), and each slot's map.
layout(std430, binding = SHADOW_SLOT_OF_LIGHT_BUFFER_BINDING) readonly buffer ShadowSlotOfLight {
    int shadowSlotOfLight[];
};
struct ShadowSlot {
    mat4 viewProjection;  // spot maps: world → clip space of the light's perspective
    vec4 params;          // x: 1 spot map, 2 cube map; y: layer of its array; z: near; w: far
};
layout(std430, binding = SHADOW_SLOTS_BUFFER_BINDING) readonly buffer ShadowSlots {
    ShadowSlot shadowSlots[];
};
layout(binding = SPOT_SHADOWS_UNIT) uniform sampler2DArrayShadow spotShadowMaps;
layout(binding = POINT_SHADOWS_UNIT) uniform samplerCubeArrayShadow pointShadowMaps;

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

// A spot light's map: perspective along its axis, 3x3 percentage-closer filter.
float spotShadow(ShadowSlot slot, vec3 position)
{
    vec4 clip = slot.viewProjection * vec4(position, 1.0);
    if (clip.w <= 0.0)
        return 1.0;
    vec3 coord = clip.xyz / clip.w * 0.5 + 0.5;
    if (any(lessThan(coord, vec3(0.0))) || any(greaterThan(coord, vec3(1.0))))
        return 1.0;
    float texel = shadowing.localShadowParams.y;
    float lit = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            lit += texture(spotShadowMaps, vec4(coord.xy + vec2(dx, dy) * texel, slot.params.y, coord.z));
    return lit / 9.0;
}

// A point light's cube map: six 90° perspective faces storing window depth, so the receiver's
// reference is the depth its major axis (the view depth on its face) gives; 3x3 taps across
// the face around the direction.
float pointShadow(ShadowSlot slot, vec3 fromLight)
{
    vec3 a = abs(fromLight);
    float major = max(a.x, max(a.y, a.z));
    float n = slot.params.z;
    float f = slot.params.w;
    if (major <= n || major >= f)
        return 1.0;
    // Window depth of a perspective projection with near n and far f at view depth `major`.
    float depth = (f + n) / (f - n) * 0.5 + 0.5 - f * n / ((f - n) * major);
    // Two directions across the major face, one texel long at the face's distance.
    vec3 u = a.x >= a.y && a.x >= a.z ? vec3(0, 1, 0) : vec3(1, 0, 0);
    vec3 v = a.z >= a.x && a.z >= a.y ? vec3(0, 1, 0) : vec3(0, 0, 1);
    float step = 2.0 * major * shadowing.localShadowParams.z;
    float lit = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            lit += texture(pointShadowMaps, vec4(fromLight + (float(dx) * u + float(dy) * v) * step, slot.params.y),
                           depth);
    return lit / 9.0;
}

// The fraction of local light `lightIndex` (at `lightPosition`) that reaches `position`.
float localShadow(uint lightIndex, vec3 lightPosition, vec3 position)
{
#ifndef LOCAL_SHADOWS
    // The variant without local shadow maps (TechniqueOptions::localShadows): llvmpipe would
    // run the lookups below under a lane mask for every (pixel, light) pair even when the
    // uniform says they are off.
    return 1.0;
#endif
    if (shadowing.localShadowParams.x == 0.0)
        return 1.0;
    int slotIndex = shadowSlotOfLight[lightIndex];
    if (slotIndex < 0)
        return 1.0;
    ShadowSlot slot = shadowSlots[slotIndex];
    return slot.params.x == 1.0 ? spotShadow(slot, position) : pointShadow(slot, position - lightPosition);
}

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
