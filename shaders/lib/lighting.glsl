// The one lighting function of docs/lighting.md. Every technique includes this file; they differ
// only in which (pixel, light) pairs they visit.
#include "lib/bindings.glsl"
#include "lib/falloff.glsl"
#include "lib/frame.glsl"
#include "lib/lights.glsl"
#include "lib/shadows.glsl"
#include "lib/specular_power.glsl"

struct Surface {
    vec3 position;  // world space
    vec3 normal;    // world space, unit
    vec3 diffuse;   // kd
    vec3 specular;  // ks
    float shininess;
    vec3 emissive;  // ke
    // kd and ks times the viewer's switches of the diffuse and specular terms (frame.terms.y,
    // .z), computed once per pixel by withTermSwitches(), which every Surface's maker calls:
    // multiplied inside the light loop, the switches (read from the frame's uniform block)
    // cost 18% of a deferred lighting pass on llvmpipe (docs/performance.md).
    vec3 switchedDiffuse;
    vec3 switchedSpecular;
};

Surface withTermSwitches(Surface s)
{
    vec2 switches = frameValues().diffuseSpecularSwitches;
    s.switchedDiffuse = switches.x * s.diffuse;
    s.switchedSpecular = switches.y * s.specular;
    return s;
}

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

// The light-independent terms: ke + ambient ⊙ kd · ao + the directional light times its
// shadow factor (lib/shadows.glsl; both factors are exactly 1 where they are off). A program
// built with NO_DIRECTIONAL_LIGHT (lightingFeatureDefines) is for scenes without one, whose
// term is zero.
vec3 shadeGlobal(Surface s, vec3 V)
{
    vec3 color = s.emissive + frame.terms.x * frame.ambient.rgb * s.diffuse * ambientOcclusion(s.position);
#ifndef NO_DIRECTIONAL_LIGHT
    color += frame.directionalIntensity.rgb * blinnPhong(s, frame.directionalToLight.xyz, V) *
             directionalShadow(s.position);
#endif
    return color;
}

// The unit direction L towards a point or spot light from `position` (xyz), and A(d) · S
// (w). w is zero where the light does not reach; the culling of every technique may only
// skip pairs for which it is zero.
//
// A program may be specialised for the lights of its scene (render/LightingPrograms.h):
// NO_SPOT_LIGHTS (S = 1 for every light), ONLY_CLASSIC_FALLOFF or ONLY_RANGE_FALLOFF (one
// kind of A). Without them every kind is evaluated and the light's own is selected, since on
// llvmpipe a branch costs both sides: the spot factor's pow and the unused falloff are paid
// by every pair in the general program.
vec4 lightReach(GpuLight light, vec3 position)
{
    vec3 toLight = light.positionRadius.xyz - position;
    float d = length(toLight);
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
    // The shadow lookup stays behind the reach test (?: evaluates one side only): a GPU then
    // skips its texture taps for the pairs out of reach.
    float shadow = reach.w != 0.0 ? localShadow(lightIndex, light.positionRadius.xyz, s.position) : 0.0;
    vec3 color = light.intensityExponent.rgb * blinnPhong(s, reach.xyz, V) * reach.w * shadow;
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
