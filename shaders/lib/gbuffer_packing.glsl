// The compact G-buffer's encodings (render/GBuffer.h: kCompactGBufferTargets), shared by the
// geometry pass that writes them and gbufferSurface() that reads them.

// Octahedral normal encoding: the unit sphere projected onto the octahedron |x|+|y|+|z| = 1,
// whose lower half is folded over the upper, gives a square [-1, 1]²; stored as unorm
// (0.5·p + 0.5) in RG16. 16-bit steps of 2/65535 in p move the normal by at most ~3e-5 rad.
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

// Shininess s ≥ 1 as a 16-bit code of log2(s) / 16 (s up to 65536), split into two unorm8
// bytes (the alpha channels of the diffuse and specular targets). One code step is a factor
// 2^(16/65535) in s: rounding changes s by ≤ 8.5e-5 relative, which moves (N·H)^s by at most
// 8.5e-5 / e ≈ 3.1e-5 of ks · intensity (max over x of x^s·|ln x|·Δs is Δs/(e·s)).
const float kShininessLog2Range = 16.0;

vec2 encodeShininess(float shininess)
{
    float code = round(clamp(log2(max(shininess, 1.0)) / kShininessLog2Range, 0.0, 1.0) * 65535.0);
    float high = floor(code / 256.0);
    return vec2(high, code - 256.0 * high) / 255.0;
}

float decodeShininess(float highByte, float lowByte)
{
    float code = round(highByte * 255.0) * 256.0 + round(lowByte * 255.0);
    return exp2(code / 65535.0 * kShininessLog2Range);
}
