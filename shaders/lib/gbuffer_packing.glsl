// The compact G-buffer's encodings (render/frame/GBuffer.h: kCompactGBufferTargets), shared by the
// geometry pass that writes them and gbufferSurface() that reads them.

// Octahedral normal encoding: the unit sphere projected onto the octahedron |x|+|y|+|z| = 1,
// whose lower half is folded over the upper, gives a square [-1, 1]²; stored as 0.5·p + 0.5
// in two 16-bit unorms. Steps of 2/65535 in p move the normal by at most ~3e-5 rad.
vec2 signNotZero(vec2 v)
{
    return vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0);
}

vec2 octahedralEncode(vec3 n)
{
    vec3 o = n / (abs(n.x) + abs(n.y) + abs(n.z));
    vec2 p = o.z >= 0.0 ? o.xy : (1.0 - abs(o.yx)) * signNotZero(o.xy);
    return 0.5 * p + 0.5;
}

vec3 octahedralDecode(vec2 stored)
{
    vec2 p = 2.0 * stored - 1.0;
    vec3 n = vec3(p, 1.0 - abs(p.x) - abs(p.y));
    if (n.z < 0.0)
        n.xy = (1.0 - abs(n.yx)) * signNotZero(n.xy);
    return normalize(n);
}

// Shininess s ≥ 1 as a 16-bit code of log2(s) / 16 (s up to 65536), split into two bytes (the
// top bytes of the surface texel's kd and ks words). One code step is a factor 2^(16/65535) in
// s: rounding changes s by ≤ 8.5e-5 relative, which moves (N·H)^s by at most 8.5e-5 / e ≈
// 3.1e-5 of ks · intensity (max over x of x^s·|ln x|·Δs is Δs/(e·s)).
const float kShininessLog2Range = 16.0;

uint encodeShininess(float shininess)
{
    return uint(round(clamp(log2(max(shininess, 1.0)) / kShininessLog2Range, 0.0, 1.0) * 65535.0));
}

float decodeShininess(uint code)
{
    return exp2(float(code) / 65535.0 * kShininessLog2Range);
}

// The compact layout's surface texel (render/frame/GBuffer.h: kCompactGBufferTargets): the view depth's
// bits, the octahedral normal as two 16-bit unorms, kd and ks as three 8-bit unorms each with a
// byte of the shininess code on top. packUnorm* round to nearest, as a unorm target's
// conversion does.
uvec4 packSurface(float viewDepth, vec3 normal, vec3 diffuse, vec3 specular, float shininess)
{
    uint code = encodeShininess(shininess);
    return uvec4(floatBitsToUint(viewDepth), packUnorm2x16(octahedralEncode(normal)),
                 packUnorm4x8(vec4(diffuse, 0.0)) | (code >> 8u) << 24u,
                 packUnorm4x8(vec4(specular, 0.0)) | (code & 255u) << 24u);
}

// The parts of a surface texel: packSurface()'s inverse, up to the rounding of the unorms and of
// the shininess code.
float surfaceViewDepth(uvec4 texel)
{
    return uintBitsToFloat(texel.x);
}

vec3 surfaceNormal(uvec4 texel)
{
    return octahedralDecode(unpackUnorm2x16(texel.y));
}

vec3 surfaceDiffuse(uvec4 texel)
{
    return unpackUnorm4x8(texel.z).rgb;
}

vec3 surfaceSpecular(uvec4 texel)
{
    return unpackUnorm4x8(texel.w).rgb;
}

float surfaceShininess(uvec4 texel)
{
    return decodeShininess((texel.z >> 24u) << 8u | texel.w >> 24u);
}

// A metallic-roughness surface's texel (docs/gbuffer.md): the kd word holds the base colour and
// the ks word metallic in its first byte, and the 16-bit code roughness in [0, 1] (steps of
// 1.5e-5). c_diff and F0 are rebuilt from them on reading, so a dielectric's F0 stays 0.04
// exactly where 8 bits of F0 would have been 0.0392.
uvec4 packMetallicRoughnessSurface(float viewDepth, vec3 normal, vec3 baseColour, float metallic, float roughness)
{
    uint code = uint(round(clamp(roughness, 0.0, 1.0) * 65535.0));
    return uvec4(floatBitsToUint(viewDepth), packUnorm2x16(octahedralEncode(normal)),
                 packUnorm4x8(vec4(baseColour, 0.0)) | (code >> 8u) << 24u,
                 packUnorm4x8(vec4(metallic, 0.0, 0.0, 0.0)) | (code & 255u) << 24u);
}

vec3 surfaceBaseColour(uvec4 texel)
{
    return unpackUnorm4x8(texel.z).rgb;
}

float surfaceMetallic(uvec4 texel)
{
    return unpackUnorm4x8(texel.w).x;
}

float surfaceRoughness(uvec4 texel)
{
    return float((texel.z >> 24u) << 8u | texel.w >> 24u) / 65535.0;
}

// The emissive target's alpha (both layouts) says the model: 1 for Blinn-Phong (as it always
// was), −1 − occlusion for metallic-roughness, whose baked occlusion it carries (a half float in
// [−2, −1] has steps of 2^-10).
float packModelOcclusion(bool metallicRoughness, float occlusion)
{
    return metallicRoughness ? -1.0 - occlusion : 1.0;
}
