#version 450 core
// Shared by the forward pass and the G-buffer pass, so both see bit-identical positions and
// normals (a technique may only differ in which lights it visits).
#include "lib/frame.glsl"
#include "lib/instances.glsl"
#include "lib/revolution.glsl"

#ifndef MATERIAL_VARIANT
#error "a mesh program is compiled for one material variant (MATERIAL_VARIANT)"
#endif

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 3) in vec4 inTangent;  // xyz tangent, w handedness; zero without uvs
layout(location = 4) in vec4 inColour;   // glTF COLOR_0; read by vertex-colour variants only

// forward's depth pre-pass and its lighting draws are different programs over this shader;
// `invariant` makes them compute the same depth bit for bit (GLSL 4.50, 4.6.1), so the
// lighting draws' GL_EQUAL passes exactly the fragments the pre-pass left visible.
invariant gl_Position;

layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;
layout(location = 2) out vec2 uv;
layout(location = 3) out vec4 worldTangent;
// The instance's material constants, read by lib/material.glsl's meshSurface().
layout(location = 4) flat out vec3 materialDiffuse;
layout(location = 5) flat out vec3 materialSpecular;
layout(location = 6) flat out float materialShininess;
layout(location = 7) flat out vec3 materialEmissive;
// Only what the variant reads (render/programs/LightingPrograms.h): every varying costs every fragment.
#if (MATERIAL_VARIANT & 128) != 0  // kSpecularTintBit
layout(location = 8) flat out vec3 materialSpecularTint;
#endif
#if (MATERIAL_VARIANT & (32 | 512)) != 0  // kAlphaMaskBit, kBlendBit
layout(location = 9) flat out vec2 materialAlpha;  // opacity, cutoff
#endif
#if (MATERIAL_VARIANT & 64) != 0  // kVertexColoursBit
layout(location = 11) out vec4 vertexColour;
#endif

void main()
{
    vec3 position = inPosition;
    vec3 normal = inNormal;
    vec4 tangent = inTangent;
    Instance instance = currentInstance();
    mat4 model = instance.model;
    if (revolutionEnabled != 0)
        revolutionSurface(inUv, position, normal, tangent);
    vec4 world = model * vec4(position, 1.0);
    worldPosition = world.xyz;
    worldNormal = instanceNormalMatrix(instance) * normal;
    uv = inUv;
    // Tangents transform with the model matrix (they lie in the surface), not the normal matrix.
    worldTangent = vec4(mat3(model) * tangent.xyz, tangent.w);
    materialDiffuse = instance.diffuse.rgb;
    materialSpecular = instance.specularShininess.rgb;
    materialShininess = instance.specularShininess.w;
    materialEmissive = instance.emissive.rgb;
#if (MATERIAL_VARIANT & 128) != 0
    materialSpecularTint = instance.specularTint.rgb;
#endif
#if (MATERIAL_VARIANT & (32 | 512)) != 0
    materialAlpha = vec2(instance.diffuse.w, instance.emissive.w);
#endif
#if (MATERIAL_VARIANT & 64) != 0
    vertexColour = inColour;
#endif
    gl_Position = frame.viewProjection * world;
}
