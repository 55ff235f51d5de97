#version 450 core
// Shadow-map pass: only depth, seen from the light (render/effects/ShadowMaps.cpp). Positions go
// through the same instance record's model matrix (lib/instances.glsl), and for a dynamic
// surface of revolution the same vertex-shader surface, as shaders/mesh.vert (DrawList sets
// both), so a receiver's world position and the caster depth stored for it agree to float
// rounding. Alpha-masked casters (MATERIAL_VARIANT with bit 5, render/programs/LightingPrograms.h
// depthOnlyVariant) also pass what their coverage needs to shadow_depth.frag.
#include "lib/frame.glsl"
#include "lib/locations.glsl"
#include "lib/instances.glsl"
#include "lib/revolution.glsl"

#ifndef MATERIAL_VARIANT
#define MATERIAL_VARIANT 0
#endif

layout(location = 0) in vec3 inPosition;
layout(location = 2) in vec2 inUv;
layout(location = 4) in vec4 inColour;

layout(location = LIGHT_VIEW_PROJECTION_LOCATION) uniform mat4 lightViewProjection;

#if (MATERIAL_VARIANT & 32) != 0
layout(location = 2) out vec2 uv;
layout(location = 9) flat out vec2 materialAlpha;  // opacity, cutoff
#if (MATERIAL_VARIANT & 64) != 0
layout(location = 11) out float vertexAlpha;
#endif
#endif

void main()
{
    vec3 position = inPosition;
    if (revolutionEnabled != 0) {
        vec3 normal;
        vec4 tangent;
        revolutionSurface(inUv, position, normal, tangent);
    }
    Instance instance = currentInstance();
    gl_Position = lightViewProjection * (instance.model * vec4(position, 1.0));
#if (MATERIAL_VARIANT & 32) != 0
    uv = inUv;
    materialAlpha = vec2(instance.diffuse.w, instance.emissive.w);
#if (MATERIAL_VARIANT & 64) != 0
    vertexAlpha = inColour.a;
#endif
#endif
}
