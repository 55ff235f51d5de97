// The one lighting function of docs/lighting.md. Every technique includes this file; they differ
// only in which (pixel, light) pairs they visit.
#include "lib/bindings.glsl"
#include "lib/falloff.glsl"
#include "lib/frame.glsl"
#include "lib/lights.glsl"
#include "lib/shadows.glsl"
#include "lib/specular_power.glsl"
#ifndef NO_ENVIRONMENT
#include "lib/environment.glsl"
#endif

// A surface of either reflection model (docs/lighting.md). Blinn-Phong reads diffuse (kd),
// specular (ks) and shininess; metallic-roughness reads diffuse as c_diff = base · (1 − metallic),
// specular as F0 = mix(0.04, base, metallic), roughness and occlusion (metallic is kept for the
// compact G-buffer, which stores the base colour and metallic rather than c_diff and F0).
struct Surface {
    vec3 position;  // world space
    vec3 normal;    // world space, unit
    vec3 diffuse;   // kd, or c_diff
    vec3 specular;  // ks, or F0
    float shininess;
    vec3 emissive;  // ke
    bool metallicRoughness;  // the model: glTF's metallic-roughness BRDF, else Blinn-Phong
    float metallic;
    float roughness;
    float occlusion;  // the material's baked ambient occlusion (1 for Blinn-Phong)
    // kd and ks times the viewer's switches of the diffuse and specular terms (frame.terms.y,
    // .z), computed once per pixel by withTermSwitches(), which every Surface's maker calls:
    // multiplied inside the light loop, the switches (read from the frame's uniform block)
    // cost 18% of a deferred lighting pass on llvmpipe (docs/performance.md).
    vec3 switchedDiffuse;
    vec3 switchedSpecular;
    float specularSwitch;  // frame.terms.z: metallic-roughness's Fresnel term is not F0 alone
    // α² = roughness⁴ of the metallic-roughness BRDF, computed once per pixel as the switches are.
    float alphaSquared;
};

// glTF's roughness is raised to at least this: at 0 the distribution D is a Dirac peak (0/0
// at N·H = 1). At 0.03 its peak 1/(π α²) is 3.9e5, within float range, and a point light's
// highlight is narrower than a pixel at any distance a scene frames.
const float kMinRoughness = 0.03;

Surface withTermSwitches(Surface s)
{
    vec2 switches = frameValues().diffuseSpecularSwitches;
    s.switchedDiffuse = switches.x * s.diffuse;
    s.switchedSpecular = switches.y * s.specular;
    s.specularSwitch = switches.y;
    float alpha = max(s.roughness, kMinRoughness) * max(s.roughness, kMinRoughness);
    s.alphaSquared = alpha * alpha;
    return s;
}

// BY_MODEL(metallicRoughness, a, b): a where the surface is shaded by the metallic-roughness
// model, b where by Blinn-Phong. A program built with NO_METALLIC_ROUGHNESS or NO_BLINN_PHONG
// (render/programs/LightingPrograms.h: the scene draws one model only) takes that model's
// expression alone and selects nothing: llvmpipe pays both sides of a select.
#if defined(NO_METALLIC_ROUGHNESS)
#define BY_MODEL(metallicRoughness, a, b) (b)
#elif defined(NO_BLINN_PHONG)
#define BY_MODEL(metallicRoughness, a, b) (a)
#else
#define BY_MODEL(metallicRoughness, a, b) ((metallicRoughness) ? (a) : (b))
#endif

// brdf(L) = kd · max(N·L, 0) + ks · max(N·H, 0)^s · [N·L > 0]
// Written without branches: llvmpipe runs 8 or 16 pixels in lock step and would execute a
// branch's body under a lane mask anyway, paying for the mask on top (docs/performance.md).
// The selects also drop the NaN that H = normalize(0) gives where L = −V.
vec3 blinnPhong(Surface s, vec3 L, vec3 V)
{
    float NdotL = dot(s.normal, L);
    vec3 H = normalize(L + V);
    vec3 brdf = s.switchedDiffuse * NdotL + s.switchedSpecular * specularPower(max(dot(s.normal, H), 0.0), s.shininess);
    return NdotL > 0.0 ? brdf : vec3(0.0);
}

const float kPi = 3.14159265358979;
// N·V is raised to at least this: a normal map may turn a visible point's normal away from the
// eye, where the visibility term would divide by zero.
const float kMinNdotV = 1e-4;

// k · ((1 − F) c_diff / π + F D Vis) · max(N·L, 0) with k = π (docs/lighting.md: so that a white
// matte surface facing a light of intensity 1 at A = 1 is lit to 1 in both models, up to 1 − F):
// glTF 2.0's BRDF (Appendix B) with the height-correlated Smith visibility. Without branches,
// for the reason blinnPhong() gives; the select drops the NaN of H = normalize(0) where L = −V.
vec3 metallicRoughnessBrdf(Surface s, vec3 L, vec3 V)
{
    float NdotL = dot(s.normal, L);
    vec3 H = normalize(L + V);
    float NdotH = max(dot(s.normal, H), 0.0);
    float oneMinusVdotH = 1.0 - max(dot(V, H), 0.0);
    float NdotV = max(dot(s.normal, V), kMinNdotV);
    float a2 = s.alphaSquared;
    float t = NdotH * NdotH * (a2 - 1.0) + 1.0;
    // π · D · Vis: D's 1/π cancels k.
    float piDVis = a2 / (t * t) * 0.5 /
                   (NdotL * sqrt(NdotV * NdotV * (1.0 - a2) + a2) + NdotV * sqrt(NdotL * NdotL * (1.0 - a2) + a2));
    float w2 = oneMinusVdotH * oneMinusVdotH;
    vec3 F = s.specular + (1.0 - s.specular) * (w2 * w2 * oneMinusVdotH);
    vec3 brdf = ((1.0 - F) * s.switchedDiffuse + (s.specularSwitch * piDVis) * F) * NdotL;
    return NdotL > 0.0 ? brdf : vec3(0.0);
}

// brdf(L) · (N·L) of the surface's model.
vec3 surfaceBrdf(Surface s, vec3 L, vec3 V)
{
    return BY_MODEL(s.metallicRoughness, metallicRoughnessBrdf(s, L, V), blinnPhong(s, L, V));
}

// Karis's analytic fit of the split-sum's (A, B) integral ("Physically based shading on mobile",
// 2014) at N·V and the roughness: the specular part of a uniform environment of radiance 1 is
// F0 · A + B.
vec2 splitSumFit(float NdotV, float roughness)
{
    vec4 r = roughness * vec4(-1.0, -0.0275, -0.572, 0.022) + vec4(1.0, 0.0425, 1.04, -0.04);
    float a004 = min(r.x * r.x, exp2(-9.28 * NdotV)) * r.x + r.y;
    return vec2(-1.04, 1.04) * a004 + r.zw;
}

// What the metallic-roughness surface reflects of a uniform environment of radiance 1: all of
// c_diff (a uniform environment's irradiance is π, which k = π's units already hold), and the
// split-sum specular F0 · A + B, times the material's baked occlusion.
vec3 metallicRoughnessAmbient(Surface s, vec3 V)
{
    vec2 ab = splitSumFit(max(dot(s.normal, V), kMinNdotV), s.roughness);
    return (s.diffuse + s.specular * ab.x + ab.y) * s.occlusion;
}

// What the surface reflects of the ambient term: kd for Blinn-Phong.
vec3 ambientReflectance(Surface s, vec3 V)
{
    return BY_MODEL(s.metallicRoughness, metallicRoughnessAmbient(s, V), s.diffuse);
}

#ifndef NO_ENVIRONMENT
// What the surface reflects of the environment (docs/lighting.md, "The environment"): a
// Blinn-Phong surface kd ⊙ E(n)/π and nothing specular; a metallic-roughness one the split-sum
// image-based light, (c_diff ⊙ E(n)/π + P(R, r) ⊙ (F0 · A + B)) · o, with P the radiance
// prefiltered for roughness r at the reflection vector R and (A, B) the fit above at N·V and r
// (unclamped, as for the ambient term).
vec3 environmentReflected(Surface s, vec3 V)
{
    vec3 diffuse = s.diffuse * environmentIrradianceOverPi(s.normal);
#ifdef NO_METALLIC_ROUGHNESS
    return diffuse;
#else
    vec2 ab = splitSumFit(max(dot(s.normal, V), kMinNdotV), s.roughness);
    vec3 specular = environmentPrefiltered(reflect(-V, s.normal), s.roughness) * (s.specular * ab.x + ab.y);
    return BY_MODEL(s.metallicRoughness, (diffuse + specular) * s.occlusion, diffuse);
#endif
}
#endif

// The light-independent terms: ke + (ambient ⊙ kd + the environment's light) · ao (kd:
// ambientReflectance(); the environment's: environmentReflected()) + the directional light
// times its shadow factor (lib/shadows.glsl; both factors are exactly 1 where they are off). A
// program built with NO_DIRECTIONAL_LIGHT (lightingFeatureDefines) is for scenes without one,
// whose term is zero; one built with NO_ENVIRONMENT for scenes without an environment, whose
// colour is then the same to the bit as before there were environments.
vec3 shadeGlobal(Surface s, vec3 V)
{
// The shadow pool's marking pass and the shadow-resolution view shade nothing (shadeLocalLight).
#if defined(SHADOW_PAGE_MARKING) || defined(SHADOW_RESOLUTION_VIEW)
    return vec3(0.0);
#endif
    vec3 color = s.emissive + frame.terms.x * frame.ambient.rgb * ambientReflectance(s, V) * ambientOcclusion(s.position);
#ifndef NO_ENVIRONMENT
    color += frame.terms.x * environmentReflected(s, V) * ambientOcclusion(s.position);
#endif
#ifndef NO_DIRECTIONAL_LIGHT
    color += frame.directionalIntensity.rgb * surfaceBrdf(s, frame.directionalToLight.xyz, V) *
             directionalShadow(s.position);
#endif
    return color;
}

// The distance d from `position` to a light at `centre`: the one computation behind every
// test of whether a light reaches a surface, lightReach's and the light lists' walks'
// (lib/cluster_lists.glsl), so that the pairs a technique evaluates and the pairs counted in
// range (shaders/in_range.comp) are the same on every driver. precise, and the sum of
// squares written out: otherwise each program may contract its multiply-adds its own way,
// and a pair at the edge of the sphere was in range for one program and not the other (one
// pair in 1.46 million on an NVIDIA H100, issue 40).
float lightDistance(vec3 centre, vec3 position)
{
    precise vec3 v = centre - position;
    precise float squared = v.x * v.x + v.y * v.y + v.z * v.z;
    return sqrt(squared);
}

// The unit direction L towards a point or spot light from `position` (xyz), and A(d) · S
// (w). w is zero where the light does not reach; the culling of every technique may only
// skip pairs for which it is zero.
//
// A program may be specialised for the lights of its scene (render/programs/LightingPrograms.h):
// NO_SPOT_LIGHTS (S = 1 for every light), ONLY_CLASSIC_FALLOFF or ONLY_RANGE_FALLOFF (one
// kind of A). Without them every kind is evaluated and the light's own is selected, since on
// llvmpipe a branch costs both sides: the spot factor's pow and the unused falloff are paid
// by every pair in the general program.
vec4 lightReach(GpuLight light, vec3 position)
{
    vec3 toLight = light.positionRadius.xyz - position;
    float d = lightDistance(light.positionRadius.xyz, position);
    // At d = 0 the direction to the light is undefined; the point gets nothing from it.
    bool reaches = d < light.positionRadius.w && d != 0.0;
    vec3 L = toLight / d;
#if defined(ONLY_CLASSIC_FALLOFF)
    float A = classicAttenuation(d, light.positionRadius.w, light.attenuation.x, light.attenuation.y,
                                 light.attenuation.z);
#elif defined(ONLY_RANGE_FALLOFF)
    float A = rangeAttenuation(d, light.attenuation.x);
#else
    float A = light.attenuation.w == 0.0
                  ? classicAttenuation(d, light.positionRadius.w, light.attenuation.x, light.attenuation.y,
                                       light.attenuation.z)
                  : rangeAttenuation(d, light.attenuation.x);
#endif
#ifdef NO_SPOT_LIGHTS
    float S = 1.0;
#else
    float S = spotFactor(dot(-L, light.spotAxisCosCutoff.xyz), light.spotAxisCosCutoff.w, light.intensityExponent.w);
#endif
    return reaches ? vec4(L, A * S) : vec4(0.0);
}

// intensity ⊙ brdf(L) · A(d) · S for local light `lightIndex`, whose record is `light`, times
// its shadow factor when it has a shadow map (lib/shadows.glsl); exactly zero where A·S is
// zero. shadeLocal() reads the record itself; shaders/volume.frag has it from its vertex shader.
vec3 shadeLocalLight(uint lightIndex, GpuLight light, Surface s, vec3 V)
{
    vec4 reach = lightReach(light, s.position);
#ifdef BRANCH_ON_REACH
    // The GPU profile's choice: a warp whose lanes are all out of the light's reach skips the
    // rest. The same value as the selects below give (zero), so the same image.
    if (reach.w == 0.0)
        return vec3(0.0);
#endif
#ifdef SHADOW_PAGE_MARKING
    // The shadow pool's marking pass (lib/shadow_pages.glsl): the pairs that would look a page
    // up below mark it instead, and nothing is shaded.
    if (reach.w != 0.0)
        markShadowPages(lightIndex, light, s.position);
    return vec3(0.0);
#endif
#ifdef SHADOW_RESOLUTION_VIEW
    // --view shadow-resolution (lib/shadows.glsl): the same pairs add up the texels per pixel
    // of the pages their lookups read instead of their light.
    return reach.w != 0.0 ? shadowResolutionTerm(lightIndex, light, s.position) : vec3(0.0);
#endif
    // The shadow lookup stays behind the reach test (?: evaluates one side only): a GPU then
    // skips its texture tap for the pairs out of reach.
    float shadow = reach.w != 0.0 ? localShadow(lightIndex, light, s.position, s.normal) : 0.0;
    vec3 color = light.intensityExponent.rgb * surfaceBrdf(s, reach.xyz, V) * reach.w * shadow;
    return reach.w != 0.0 ? color : vec3(0.0);
}

vec3 shadeLocal(uint lightIndex, Surface s, vec3 V)
{
    return shadeLocalLight(lightIndex, batchLight(lightIndex), s, V);
}

// Work counting (--count-work): the shaders of each technique report how many (pixel,
// light) pairs they evaluated, into an image the renderer sums. Helper invocations' atomics
// have no effect, so only real pixels count.
// Compute shaders name the pixel; fragment shaders may leave it to gl_FragCoord (compute
// shaders define LIGHTING_IN_COMPUTE before including this file, where gl_FragCoord does
// not exist).
#ifdef COUNT_WORK
layout(binding = LIGHT_EVALUATIONS_IMAGE_UNIT, r32ui) uniform coherent uimage2D lightEvaluations;
void recordLightEvaluationsAt(ivec2 pixel, uint count)
{
    imageAtomicAdd(lightEvaluations, pixel, count);
}
#else
void recordLightEvaluationsAt(ivec2 pixel, uint count) {}
#endif
#ifndef LIGHTING_IN_COMPUTE
void recordLightEvaluations(uint count)
{
    recordLightEvaluationsAt(ivec2(gl_FragCoord.xy), count);
}
#endif

vec3 viewVector(vec3 position)
{
    return normalize(frameValues().eye - position);
}
