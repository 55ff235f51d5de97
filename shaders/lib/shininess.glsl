// The Blinn-Phong exponent of glTF's metallic-roughness materials, and the largest shininess
// any material gets (docs/scene-format.md).
//
// This file is compiled twice: as GLSL (included by lib/material.glsl, which maps a
// metallic-roughness map per texel) and as C++ (included by scene/Shininess.cpp, which maps a
// material's factors and clamps MTL shininess), so the loaders and the shaders cannot drift
// apart. It is therefore written in the common subset of both languages: float literals with
// an f suffix, no vectors, no overloads.

// Above this, MTL and glTF shininess values add nothing visible and only risk pow() overflow.
const int MAX_SHININESS = 2048;

// The Blinn-Phong exponent for a glTF roughness: roughness⁴ is the Beckmann slope variance
// (α = roughness², GGX's convention) whose matching Blinn-Phong exponent is 2/α² − 2, clamped
// to [1, MAX_SHININESS].
float blinnPhongExponent(float roughness)
{
    float r2 = max(roughness, 1e-3f) * max(roughness, 1e-3f);
    return clamp(2.0f / (r2 * r2) - 2.0f, 1.0f, float(MAX_SHININESS));
}
