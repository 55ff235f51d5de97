#version 450 core
// Shadow-map pass: only depth, seen from the light (render/ShadowMaps.cpp). Positions go
// through the same model matrix as shaders/mesh.vert, so a receiver's world position and
// the caster depth stored for it agree to float rounding.
layout(location = 0) in vec3 inPosition;

layout(location = 0) uniform mat4 model;
layout(location = 20) uniform mat4 lightViewProjection;

void main()
{
    gl_Position = lightViewProjection * (model * vec4(inPosition, 1.0));
}
