// Per-draw material inputs and the surface a mesh fragment describes. Both forward.frag and
// gbuffer.frag call meshSurface(), so every technique shades the same surface: the same
// triangles rasterised with the same uv derivatives choose the same mip levels (implicit LOD)
// in both passes, so the texture lookups need no explicit LOD to agree.
// The material constants come per instance from the vertex shader (shaders/mesh.vert reads
// them from lib/instances.glsl), so one instanced draw can show many materials; the maps
// below stay per draw, and only draws without maps are instanced (render/GpuScene.cpp).
layout(location = 4) flat in vec3 materialDiffuse;
layout(location = 5) flat in vec3 materialSpecular;
layout(location = 6) flat in float materialShininess;
layout(location = 7) flat in vec3 materialEmissive;
// Which maps the material has: bit 0 diffuse, bit 1 specular, bit 2 normal, bit 3 emissive
// (render/LightingPrograms.h: MaterialMapSet). A missing map leaves the constant as it is.
// A compile-time constant, one program per set: llvmpipe runs both sides of a branch under a
// lane mask, so branching on a uniform would pay every map's lookups for every fragment.
#ifndef MATERIAL_MAPS
#error "a mesh program is compiled for one set of material maps (MATERIAL_MAPS)"
#endif
const int materialMaps = MATERIAL_MAPS;
layout(location = 15) uniform float materialNormalScale;  // glTF normalTexture.scale

layout(binding = 6) uniform sampler2D diffuseMap;   // sRGB storage: samples are linear kd
layout(binding = 7) uniform sampler2D specularMap;  // linear
layout(binding = 8) uniform sampler2D normalMap;    // tangent space, OpenGL convention (+Y up)
// Unit 15: units 9-14 hold the shadow and occlusion maps (shaders/lib/shadows.glsl).
layout(binding = 15) uniform sampler2D emissiveMap;  // sRGB storage (glTF emissiveTexture, MTL map_Ke)

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 2) in vec2 uv;
layout(location = 3) in vec4 worldTangent;  // xyz tangent, w handedness (scene/Tangents.h)

const int kHasDiffuseMap = 1;
const int kHasSpecularMap = 2;
const int kHasNormalMap = 4;
const int kHasEmissiveMap = 8;

// The normal map's tangent-space normal, taken to world space: the interpolated tangent is
// re-orthogonalised against the interpolated normal (Gram-Schmidt) and B = w · cross(N, T),
// as MikkTSpace-baked maps expect. A vertex without a tangent frame keeps the geometric normal.
vec3 normalMapped(vec3 N)
{
    vec3 T = worldTangent.xyz - N * dot(N, worldTangent.xyz);
    if (dot(T, T) <= 1e-20)
        return N;
    T = normalize(T);
    vec3 B = (worldTangent.w < 0.0 ? -1.0 : 1.0) * cross(N, T);
    vec3 t = texture(normalMap, uv).xyz * 2.0 - 1.0;
    t.xy *= materialNormalScale;
    vec3 mapped = T * t.x + B * t.y + N * t.z;
    return dot(mapped, mapped) > 0.0 ? normalize(mapped) : N;
}

Surface meshSurface()
{
    Surface s;
    s.position = worldPosition;
    s.normal = normalize(worldNormal);
    s.diffuse = materialDiffuse;
    s.specular = materialSpecular;
    // materialMaps is a constant, so the compiler drops the branches of absent maps and the
    // implicit derivatives of texture() are defined.
    if ((materialMaps & kHasDiffuseMap) != 0)
        s.diffuse *= texture(diffuseMap, uv).rgb;
    if ((materialMaps & kHasSpecularMap) != 0)
        s.specular *= texture(specularMap, uv).rgb;
    if ((materialMaps & kHasNormalMap) != 0)
        s.normal = normalMapped(s.normal);
    s.shininess = materialShininess;
    s.emissive = materialEmissive;
    if ((materialMaps & kHasEmissiveMap) != 0)
        s.emissive *= texture(emissiveMap, uv).rgb;
    return withTermSwitches(s);
}
