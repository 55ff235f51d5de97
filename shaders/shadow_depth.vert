#version 450 core
// Shadow-map pass: only depth, seen from the light (render/ShadowMaps.cpp). Positions go
// through the same instance record's model matrix (lib/instances.glsl), and for a dynamic
// surface of revolution the same vertex-shader surface, as shaders/mesh.vert (GpuScene sets
// both), so a receiver's world
// position and the caster depth stored for it agree to float rounding.
#include "lib/frame.glsl"
#include "lib/instances.glsl"
#include "lib/revolution.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 2) in vec2 inUv;

layout(location = 20) uniform mat4 lightViewProjection;

void main()
{
    vec3 position = inPosition;
    if (revolutionEnabled != 0) {
        vec3 normal;
        vec4 tangent;
        revolutionSurface(inUv, position, normal, tangent);
    }
    gl_Position = lightViewProjection * (currentInstance().model * vec4(position, 1.0));
}
