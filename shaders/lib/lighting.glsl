// The one lighting function of docs/lighting.md. Every technique includes this file; they differ
// only in which (pixel, light) pairs they visit.
#include "lib/bindings.glsl"
#include "lib/falloff.glsl"
#include "lib/frame.glsl"
#include "lib/lights.glsl"
#include "lib/shadows.glsl"

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

// x^n for x in [0, 1] and a constant integer n in [1, 4095] by multiplications: x, x², x⁴, ...
// and the product of the powers n's bits select. The loop's bounds and n are constants, so the
// compiler unrolls it and keeps only the multiplications n needs (render/LightingPrograms.h
// integerPowerMultiplications). Exact to a few ulps, as pow(), except that a power below 2^-126
// (a subnormal float, 1.2e-38) is 0: x is flushed where x^n would be, so that every value in the
// chain, all at least x^n, stays normal. A multiplication that reads or makes a subnormal takes a
// microcode assist of about a hundred cycles on x86, and llvmpipe does not set flush-to-zero:
// without the flush, shininess 255 cost more than pow() (docs/performance.md).
float integerPower(float x, uint n)
{
    float power = 1.0;
    float square = x < exp2(-126.0 / float(n)) ? 0.0 : x;  // x^(2^bit)
    for (uint bit = 0u; bit < 12u; ++bit) {
        if ((n & (1u << bit)) != 0u)
            power *= square;
        square *= square;
    }
    return power;
}

// x^shininess for x in [0, 1]. pow() is exp2(shininess · log2(x)), whose two polynomials cost
// a quarter of a lighting pass on llvmpipe (docs/performance.md). A program built with
// SPECULAR_EXPONENT_COUNT k and SPECULAR_EXPONENTS, k ascending integers (render/LightingPrograms.h:
// the shininesses of every surface of the scene with a specular term, where their
// multiplications are few), multiplies instead: each power is computed, and the surface's
// shininess picks its own by the midpoints between them, which a compact G-buffer's decoded
// shininess (within 0.01% of the material's) never crosses. The loop's bounds are constants:
// it unrolls, and the exponents become constants of each integerPower.
#ifdef SPECULAR_EXPONENT_COUNT
const uint kSpecularExponents[SPECULAR_EXPONENT_COUNT] = uint[](SPECULAR_EXPONENTS);
#endif
float specularPower(float x, float shininess)
{
#ifdef SPECULAR_EXPONENT_COUNT
    float power = integerPower(x, kSpecularExponents[0]);
    for (int i = 1; i < SPECULAR_EXPONENT_COUNT; ++i) {
        float next = integerPower(x, kSpecularExponents[i]);
        power = shininess > 0.5 * float(kSpecularExponents[i - 1] + kSpecularExponents[i]) ? next : power;
    }
    return power;
#else
    return pow(x, shininess);
#endif
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
