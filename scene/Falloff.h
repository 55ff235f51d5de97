// CPU side of the shared falloff code (shaders/lib/falloff.glsl, compiled here as C++).
#pragma once

#include "scene/Scene.h"

namespace manylights {

namespace falloff {
extern const float kUnboundedRadius;
float classicRadius(float c, float b, float a, float imax, float threshold);
float classicAttenuation(float d, float radius, float c, float b, float a);
float rangeAttenuation(float d, float r);
float spotFactor(float cosTheta, float cosCutoff, float exponent);
}  // namespace falloff

// The distance beyond which the light contributes nothing (A(d) = 0): the culling radius
// every technique uses. falloff::kUnboundedRadius for an unbounded classic light.
float lightRadius(const Light& light, float attenuationThreshold);

}  // namespace manylights
