#version 450 core
// The moving lights posed on the GPU (render/scene/SceneLights.h), once per frame whose time
// moved them: an invocation per animated light evaluates its motion (scene/Animation.cpp,
// docs/scene-format.md "Animation") at the frame's time and writes the light's position into
// the lights' buffer, which every later pass of the frame reads. The motions were uploaded
// once: a frame of a million moving lights is one dispatch, not a million poses on the CPU and
// a 64 MiB upload.
//
// The same arithmetic as the CPU's animatedPosition: angles and fractions of a turn are
// reduced in double before they become floats (at t = 10^4 s a float angle is already off by
// a visible fraction of a degree), then the sine and cosine are taken in float. The two agree
// to within the float sine's rounding (tests/gl/SceneLightsTest.cpp).
//
// Workgroups in rows (render/programs/WorkgroupRows.h: x up to 32,768, then z), so the
// dispatch covers the format's 16,777,216 lights. No loop.
#include "lib/bindings.glsl"
#include "lib/locations.glsl"
#include "lib/listed_dispatch.glsl"

layout(local_size_x = 64) in;

// render/scene/SceneLights.h: GpuLightMotion.
struct LightMotion {
    vec4 restPosition;  // xyz: the position at rest; w: the light's index, as bits
    vec4 settings;      // orbit: (radius, degrees per second, phase degrees, 0); drift: (amplitude xyz, phase degrees)
    vec4 periods;       // drift: the period of each axis in seconds; w: the kind (POSE_ORBIT, POSE_DRIFT), as bits
};

layout(std430, binding = LIGHT_MOTIONS_BUFFER_BINDING) readonly buffer LightMotions {
    LightMotion motion[];
};
// lib/lights.glsl's GpuLight as four vec4 per light, of which this pass writes the position.
layout(std430, binding = LIGHTS_BUFFER_BINDING) writeonly buffer Lights {
    vec4 lightVec4[];
};

layout(location = POSE_TIME_LOCATION) uniform double time;
layout(location = POSE_MOTION_COUNT_LOCATION) uniform uint motionCount;

const double TWO_PI = 6.283185307179586LF;

// sin(2π · turns), the turns reduced to [0, 1) in double first.
float sinTurns(double turns)
{
    return sin(float(TWO_PI * (turns - floor(turns))));
}

vec3 orbitOffset(LightMotion m)
{
    // std::fmod's remainder (it keeps the sign), then degrees to radians in float.
    double degrees = double(m.settings.z) + double(m.settings.y) * time;
    degrees -= 360.0LF * trunc(degrees / 360.0LF);
    float angle = radians(float(degrees));
    return m.settings.x * vec3(cos(angle), 0.0, sin(angle));
}

vec3 driftOffset(LightMotion m)
{
    double phaseTurns = double(m.settings.w) / 360.0LF;
    vec3 offset;
    for (int i = 0; i < 3; ++i)
        offset[i] = m.settings[i] * sinTurns(time / double(m.periods[i]) + phaseTurns);
    return offset;
}

void main()
{
    uint index = listedGroup() * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (index >= motionCount)
        return;
    LightMotion m = motion[index];
    uint kind = floatBitsToUint(m.periods.w);
    vec3 offset = kind == POSE_ORBIT ? orbitOffset(m) : driftOffset(m);
    lightVec4[floatBitsToUint(m.restPosition.w) * 4u].xyz = m.restPosition.xyz + offset;
}
