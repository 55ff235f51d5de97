#version 450 core
// The shadow-page pool's casters (render/shadows/ShadowPool.cpp): one instanced draw per batch
// of the scene's items draws each item into every face part it may meet, an instance per
// (item, face part) pair. The part's record maps the face's clip space into its square of the
// depth atlas, and four clip distances keep the triangles inside that square. Positions go
// through the same instance record and surface of revolution as shaders/mesh.vert, as in
// shadow_depth.vert, whose fragment shader (shadow_depth.frag) cuts alpha-masked casters.
#include "lib/bindings.glsl"
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

// x: the item's instance record; y: the face part's draw record.
layout(std430, binding = SHADOW_CASTER_FACES_BUFFER_BINDING) readonly buffer CasterFaces {
    uvec2 casterFaces[];
};
// std430 layout of render/shadows/ShadowPool.cpp: GpuFaceDraw.
struct FaceDraw {
    mat4 viewProjection;  // world → the face's clip space
    vec4 toAtlas;         // face clip xy → atlas clip xy: xy · toAtlas.xy + w · toAtlas.zw
    vec4 square;          // the part's square in atlas NDC: x0, y0, x1, y1
};
layout(std430, binding = SHADOW_FACE_DRAWS_BUFFER_BINDING) readonly buffer FaceDraws {
    FaceDraw faceDraws[];
};
layout(location = SHADOW_CASTER_FACE_BASE_LOCATION) uniform int casterFaceBase;

out float gl_ClipDistance[4];

#if (MATERIAL_VARIANT & 32) != 0
layout(location = 2) out vec2 uv;
layout(location = 9) flat out vec2 materialAlpha;  // opacity, cutoff
#if (MATERIAL_VARIANT & 64) != 0
layout(location = 11) out float vertexAlpha;
#endif
#endif

void main()
{
    uvec2 pair = casterFaces[casterFaceBase + gl_InstanceID];
    Instance instance = instances[pair.x];
    FaceDraw draw = faceDraws[pair.y];
    vec3 position = inPosition;
    if (revolutionEnabled != 0) {
        vec3 normal;
        vec4 tangent;
        revolutionSurface(inUv, position, normal, tangent);
    }
    vec4 clip = draw.viewProjection * (instance.model * vec4(position, 1.0));
    clip.xy = clip.xy * draw.toAtlas.xy + clip.w * draw.toAtlas.zw;
    gl_Position = clip;
    gl_ClipDistance[0] = clip.x - draw.square.x * clip.w;
    gl_ClipDistance[1] = draw.square.z * clip.w - clip.x;
    gl_ClipDistance[2] = clip.y - draw.square.y * clip.w;
    gl_ClipDistance[3] = draw.square.w * clip.w - clip.y;
#if (MATERIAL_VARIANT & 32) != 0
    uv = inUv;
    materialAlpha = vec2(instance.diffuse.w, instance.emissive.w);
#if (MATERIAL_VARIANT & 64) != 0
    vertexAlpha = inColour.a;
#endif
#endif
}
