#version 450 core
#define FRAME_VALUES_OUT  // for volume.frag (lib/frame.glsl)
// One instance per light: the bounding sphere or cone (render/volumes/LightVolumes.h) placed and
// scaled from the light buffer, or, for unbounded lights, a triangle covering the screen.
#include "lib/bindings.glsl"
#include "lib/frame.glsl"
#include "lib/lights.glsl"

layout(location = 0) in vec3 inPosition;

// The lights of each shape, as indices into the light buffer.
layout(std430, binding = VOLUME_LIGHTS_BUFFER_BINDING) readonly buffer VolumeLights {
    uint volumeLights[];
};

layout(location = 0) uniform uint firstVolumeLight;  // where this draw's lights begin
layout(location = 1) uniform int volumeShape;        // 0 sphere, 1 cone, 2 full screen

layout(location = 0) flat out uint lightIndex;
layout(location = 1) flat out GpuLight volumeLight;

const int SHAPE_SPHERE = 0;
const int SHAPE_CONE = 1;

void main()
{
    lightIndex = volumeLights[firstVolumeLight + uint(gl_InstanceID)];
    GpuLight light = lights[lightIndex];
    volumeLight = light;
    passFrameValues();
    vec3 centre = light.positionRadius.xyz;
    float radius = light.positionRadius.w;
    if (volumeShape == SHAPE_SPHERE) {
        gl_Position = frame.viewProjection * vec4(centre + radius * inPosition, 1.0);
    } else if (volumeShape == SHAPE_CONE) {
        vec3 axis = light.spotAxisCosCutoff.xyz;
        float cosCutoff = light.spotAxisCosCutoff.w;
        float baseRadius = radius * sqrt(max(1.0 - cosCutoff * cosCutoff, 0.0)) / cosCutoff;
        vec3 helper = abs(axis.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
        vec3 u = normalize(cross(helper, axis));
        vec3 v = cross(axis, u);
        vec3 world = centre + baseRadius * (inPosition.x * u + inPosition.y * v) + radius * inPosition.z * axis;
        gl_Position = frame.viewProjection * vec4(world, 1.0);
    } else {
        vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
        gl_Position = vec4(corner * 2.0 - 1.0, 1.0, 1.0);
    }
}
