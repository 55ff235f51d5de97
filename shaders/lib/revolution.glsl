// The dynamic surface of revolution of scene/Revolution.h, computed in the vertex shader from
// the mesh's uvs and the frame time (the mesh is only its (u, v) grid). Same formulas as
// revolutionPosition / revolutionNormal on the CPU, which the tests compare it against:
//     r(v, t) = radius + amplitude · sin(2π · (waves · v − fract(speed · t)))
//     P = (r cos 2πu, height · v, r sin 2πu),  N ∝ (height cos 2πu, −∂r/∂v, height sin 2πu)
// Needs lib/frame.glsl for the time. Uniform locations in lib/locations.glsl (issue 6's range).
#include "lib/locations.glsl"
layout(location = REVOLUTION_ENABLED_LOCATION) uniform int revolutionEnabled;  // 0: an ordinary mesh
layout(location = REVOLUTION_SHAPE_LOCATION) uniform vec4 revolutionShape;     // radius, height, amplitude, waves
layout(location = REVOLUTION_SPEED_LOCATION) uniform float revolutionSpeed;    // crests per second

const float kRevolutionTwoPi = 6.28318530718;

// Object-space position, unit normal and tangent (along u, handedness 1) at `uv`.
void revolutionSurface(vec2 uv, out vec3 position, out vec3 normal, out vec4 tangent)
{
    float radius = revolutionShape.x;
    float height = revolutionShape.y;
    float amplitude = revolutionShape.z;
    float waves = revolutionShape.w;
    float phase = kRevolutionTwoPi * (waves * uv.y - fract(revolutionSpeed * frame.time.x));
    float r = radius + amplitude * sin(phase);
    float slope = amplitude * kRevolutionTwoPi * waves * cos(phase);
    float angle = kRevolutionTwoPi * uv.x;
    vec2 around = vec2(cos(angle), sin(angle));
    position = vec3(r * around.x, height * uv.y, r * around.y);
    normal = normalize(vec3(height * around.x, -slope, height * around.y));
    tangent = vec4(-around.y, 0.0, around.x, 1.0);
}
