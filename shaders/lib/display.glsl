// The display transform of docs/display.md: exposure, then a tone curve, then the sRGB
// encoding, each on linear RGB. render/effects/DisplayPass.cpp compiles shaders/display.frag with
// TONE_CURVE (0 none, 1 reinhard, 2 aces, 3 agx, 4 pbr-neutral: scene/DisplaySettings.h's order) and
// SRGB_ENCODE as constants, so a frame pays only for the curve it uses.

// Reinhard, Stark, Shirley and Ferwerda, "Photographic Tone Reproduction for Digital
// Images", SIGGRAPH 2002, eq. 3 (L / (1 + L)), applied to each channel.
vec3 reinhardCurve(vec3 x)
{
    return x / (1.0 + x);
}

// Narkowicz, "ACES Filmic Tone Mapping Curve" (2015): a rational fit of the ACES reference
// rendering and output transforms' tone scale, x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14).
vec3 acesCurve(vec3 x)
{
    return clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

// Sobotka's AgX (github.com/sobotka/AgX) as fitted by Wrensch, "Minimal AgX Implementation"
// (2023): an inset matrix, log2 encoding between −12.47393 and +4.026069 stops around 0.18,
// the default contrast sigmoid as a 6th-order polynomial, the outset matrix. The result, in
// [0, 1], is display-encoded for a 2.2 power display.
vec3 agxEncoded(vec3 x)
{
    const mat3 inset = mat3(0.842479062253094, 0.0423282422610123, 0.0423756549057051,
                            0.0784335999999992, 0.878468636469772, 0.0784336,
                            0.0792237451477643, 0.0791661274605434, 0.879142973793104);
    const mat3 outset = mat3(1.19687900512017, -0.0528968517574562, -0.0529716355144438,
                             -0.0980208811401368, 1.15190312990417, -0.0980434501171241,
                             -0.0990297440797205, -0.0989611768448433, 1.15107367264116);
    const float minStops = -12.47393;
    const float maxStops = 4.026069;
    vec3 v = inset * max(x, vec3(0.0));
    // log2(0) is −inf; the clamp takes it to the bottom of the range.
    v = (clamp(log2(max(v, vec3(1e-10))), minStops, maxStops) - minStops) / (maxStops - minStops);
    vec3 v2 = v * v;
    vec3 v4 = v2 * v2;
    v = 15.5 * v4 * v2 - 40.14 * v4 * v + 31.96 * v4 - 6.868 * v2 * v + 0.4298 * v2 + 0.1191 * v - 0.00232;
    return clamp(outset * v, 0.0, 1.0);
}

// AgX as linear display light: raising Wrensch's output to 2.2 undoes the 2.2 power display's
// encoding, so that the sRGB encoding below (or none) applies to every curve alike.
vec3 agxCurve(vec3 x)
{
    return pow(agxEncoded(x), vec3(2.2));
}

// Khronos PBR Neutral (github.com/KhronosGroup/ToneMapping, PBR_Neutral, 2024), as its
// specification states it. Below a peak channel of 0.76 the colour is only lowered by a small
// offset (0.04, Fresnel's reflection at normal incidence that lifts every dielectric; below a
// darkest channel of 0.08 the quadratic t - 6.25 t^2, which meets it with a level slope at
// 0.08 and keeps black black), so base colours show as authored. Above it the peak is
// compressed towards 1 by 1 - d^2 / (peak + d - 0.76), d = 0.24 (continuous in value and
// slope at 0.76), every channel scaled alike so the hue holds, and the colour moved towards
// the compressed grey by g = 1 - 1 / (0.15 (peak - compressed) + 1): only light far past
// white loses its saturation.
vec3 pbrNeutralCurve(vec3 colour)
{
    const float compressionStart = 0.8 - 0.04;
    const float desaturation = 0.15;
    const float headroom = 1.0 - compressionStart;
    colour = max(colour, vec3(0.0));
    float darkest = min(colour.r, min(colour.g, colour.b));
    colour -= darkest < 0.08 ? darkest - 6.25 * darkest * darkest : 0.04;
    float peak = max(colour.r, max(colour.g, colour.b));
    if (peak < compressionStart)
        return colour;
    float compressedPeak = 1.0 - headroom * headroom / (peak + headroom - compressionStart);
    colour *= compressedPeak / peak;
    float towardsWhite = 1.0 - 1.0 / (desaturation * (peak - compressedPeak) + 1.0);
    return mix(colour, vec3(compressedPeak), towardsWhite);
}

vec3 toneCurve(vec3 x)
{
#if TONE_CURVE == 1
    return reinhardCurve(x);
#elif TONE_CURVE == 2
    return acesCurve(x);
#elif TONE_CURVE == 3
    return agxCurve(x);
#elif TONE_CURVE == 4
    return pbrNeutralCurve(x);
#else
    return x;
#endif
}

// IEC 61966-2-1 (sRGB) encoding: 12.92 c below 0.0031308, 1.055 c^(1/2.4) − 0.055 above.
vec3 srgbEncode(vec3 c)
{
    c = clamp(c, 0.0, 1.0);
    vec3 low = 12.92 * c;
    vec3 high = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
    return mix(high, low, lessThanEqual(c, vec3(0.0031308)));
}

// AgX, then the sRGB encoding, with one log2 where agxCurve and srgbEncode take two (each pow
// is a log2 and an exp2): sRGB of c^2.2 is 12.92 c^2.2 up to c^2.2 = 0.0031308, that is up to
// c = 0.0031308^(1/2.2) = 0.072721, and 1.055 c^(2.2/2.4) − 0.055 above. The same function,
// not an approximation of it: the default look (scene/DisplaySettings.h) runs on every frame,
// and on llvmpipe the transcendental functions are most of its arithmetic (docs/display.md).
vec3 agxSrgbEncoded(vec3 x)
{
    vec3 c = agxEncoded(x);
    vec3 stops = log2(max(c, vec3(1e-10)));  // log2(0) is undefined; 1e-10 gives 0 in 8 bits
    vec3 low = 12.92 * exp2(2.2 * stops);
    vec3 high = 1.055 * exp2((2.2 / 2.4) * stops) - 0.055;
    return mix(high, low, lessThanEqual(c, vec3(0.072721)));
}

vec3 displayTransform(vec3 linear, float exposureScale)
{
#if TONE_CURVE == 3 && defined(SRGB_ENCODE)
    return agxSrgbEncoded(linear * exposureScale);
#else
    vec3 c = toneCurve(linear * exposureScale);
#ifdef SRGB_ENCODE
    c = srgbEncode(c);
#endif
    return c;
#endif
}
