#include "scene/Falloff.h"

#include <algorithm>
#include <cmath>

namespace manylights::falloff {

namespace shared_source {
// The GLSL built-ins falloff.glsl calls, taken from the standard library for floats.
using std::max;
using std::pow;
using std::sqrt;
#include "lib/falloff.glsl"
}  // namespace shared_source

const float kUnboundedRadius = shared_source::UNBOUNDED_RADIUS;

float classicRadius(float c, float b, float a, float imax, float threshold)
{
    return shared_source::classicRadius(c, b, a, imax, threshold);
}

float classicAttenuation(float d, float radius, float c, float b, float a)
{
    return shared_source::classicAttenuation(d, radius, c, b, a);
}

float rangeAttenuation(float d, float r) { return shared_source::rangeAttenuation(d, r); }

float spotFactor(float cosTheta, float cosCutoff, float exponent)
{
    return shared_source::spotFactor(cosTheta, cosCutoff, exponent);
}

}  // namespace manylights::falloff

namespace manylights {

float lightRadius(const Light& light, float attenuationThreshold)
{
    if (light.falloff == Falloff::Range)
        return light.range;
    const float imax = std::max({light.intensity.r, light.intensity.g, light.intensity.b});
    const ClassicAttenuation& k = light.attenuation;
    return falloff::classicRadius(k.constant, k.linear, k.quadratic, imax, attenuationThreshold);
}

}  // namespace manylights
