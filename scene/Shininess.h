// The Blinn-Phong exponent of glTF's metallic-roughness materials and the largest shininess,
// from shaders/lib/shininess.glsl (compiled as C++ by Shininess.cpp), so the loaders and
// shaders/lib/material.glsl share one source.
#pragma once

namespace manylights {

// Above this, MTL and glTF shininess values add nothing visible and only risk pow() overflow.
extern const float kMaxShininess;

// The Blinn-Phong exponent for a glTF roughness: roughness⁴ is the Beckmann slope variance
// (α = roughness², GGX's convention) whose matching Blinn-Phong exponent is 2/α² − 2, clamped
// to [1, kMaxShininess]. shaders/lib/material.glsl computes the same per texel.
float blinnPhongExponent(float roughness);

}  // namespace manylights
