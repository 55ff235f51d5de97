#include "scene/Shininess.h"

#include <algorithm>

namespace manylights {

namespace shared_source {
// The GLSL built-ins shininess.glsl calls, taken from the standard library for floats (the
// same float operations as the shader's).
using std::clamp;
using std::max;
#include "lib/shininess.glsl"
}  // namespace shared_source

const float kMaxShininess = float(shared_source::MAX_SHININESS);

float blinnPhongExponent(float roughness) { return shared_source::blinnPhongExponent(roughness); }

}  // namespace manylights
