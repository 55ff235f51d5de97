// Per-draw material inputs and the surface a mesh fragment describes. Both forward.frag and
// gbuffer.frag call meshSurface(), so every technique shades the same surface: the same
// triangles rasterised with the same uv derivatives choose the same mip levels (implicit LOD)
// in both passes, so the texture lookups need no explicit LOD to agree.
// The material constants come per instance from the vertex shader (shaders/mesh.vert reads
// them from lib/instances.glsl), so one instanced draw can show many materials; the maps
// below stay per draw, and only draws without maps are instanced (render/scene/DrawList.cpp).
#include "lib/bindings.glsl"
#include "lib/locations.glsl"
layout(location = 4) flat in vec3 materialDiffuse;
layout(location = 5) flat in vec3 materialSpecular;
layout(location = 6) flat in float materialShininess;
layout(location = 7) flat in vec3 materialEmissive;
// What the material reads: bit 0 diffuse map, 1 specular map, 2 normal map, 3 emissive map,
// 4 metallic-roughness map, 5 alpha mask, 6 vertex colours, 7 specular tint, 8 back faces lit
// with the reversed normal, 9 blended, 10 opacity map, 11 uv transforms, 12 the metallic-roughness
// model, 13 occlusion map (render/programs/LightingPrograms.h: MaterialVariant). A missing map leaves
// the constant as it is. A compile-time constant, one program per variant: llvmpipe runs both
// sides of a branch under a lane mask, so branching on a uniform would pay every map's lookups
// for every fragment, a discard that can never run would still keep the depth test from running
// before the shader, and every input costs every fragment.
#ifndef MATERIAL_VARIANT
#error "a mesh program is compiled for one material variant (MATERIAL_VARIANT)"
#endif
const int materialVariant = MATERIAL_VARIANT;
#if (MATERIAL_VARIANT & 128) != 0
layout(location = 8) flat in vec3 materialSpecularTint;  // base colour · metallic (scene/Scene.h)
#else
const vec3 materialSpecularTint = vec3(0.0);
#endif
#if (MATERIAL_VARIANT & (32 | 512)) != 0
layout(location = 9) flat in vec2 materialAlpha;  // opacity, alpha cutoff
#endif
#if (MATERIAL_VARIANT & 64) != 0
layout(location = 11) in vec4 vertexColour;  // glTF COLOR_0
#endif
layout(location = MATERIAL_NORMAL_SCALE_LOCATION) uniform float materialNormalScale;  // glTF normalTexture.scale
// glTF metallicFactor and roughnessFactor, for the metallic-roughness map's per-texel mapping.
layout(location = MATERIAL_METALLIC_ROUGHNESS_LOCATION) uniform vec2 materialMetallicRoughness;
// Each map's uv transform (glTF KHR_texture_transform; scene/Scene.h Material::uvTransforms),
// after the light batch's location 40 (render/programs/LightBatches.h):
// uv' = M · (u, v, 1). Set per draw for the maps the draw binds.
layout(location = DIFFUSE_UV_TRANSFORM_LOCATION) uniform mat3x2 diffuseUvTransform;
layout(location = SPECULAR_UV_TRANSFORM_LOCATION) uniform mat3x2 specularUvTransform;  // also the metallic-roughness map's
layout(location = NORMAL_UV_TRANSFORM_LOCATION) uniform mat3x2 normalUvTransform;
layout(location = EMISSIVE_UV_TRANSFORM_LOCATION) uniform mat3x2 emissiveUvTransform;
layout(location = OPACITY_UV_TRANSFORM_LOCATION) uniform mat3x2 opacityUvTransform;
layout(location = OCCLUSION_UV_TRANSFORM_LOCATION) uniform mat3x2 occlusionUvTransform;

layout(binding = DIFFUSE_MAP_UNIT) uniform sampler2D diffuseMap;   // sRGB storage: samples are linear kd
// Linear. A Blinn-Phong specular map, or (bit 4) glTF's metallic-roughness map: G roughness,
// B metallic. A material has one or the other.
layout(binding = SPECULAR_MAP_UNIT) uniform sampler2D specularMap;
layout(binding = NORMAL_MAP_UNIT) uniform sampler2D normalMap;    // tangent space, OpenGL convention (+Y up)
// Unit 15: units 9-14 hold the shadow and occlusion maps (shaders/lib/shadows.glsl).
layout(binding = EMISSIVE_MAP_UNIT) uniform sampler2D emissiveMap;
layout(binding = OPACITY_MAP_UNIT) uniform sampler2D opacityMap;  // red channel: a coverage factor  // sRGB storage (glTF emissiveTexture, MTL map_Ke)
// Linear, red channel: glTF occlusionTexture, the metallic-roughness model's baked occlusion.
layout(binding = OCCLUSION_MAP_UNIT) uniform sampler2D occlusionMap;

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 2) in vec2 uv;
layout(location = 3) in vec4 worldTangent;  // xyz tangent, w handedness (scene/Tangents.h)

// The uv a map is sampled at: its transform times (u, v, 1). A material whose transforms are all
// the identity (variant bit 11 clear) takes uv as it is, which the product would give exactly:
// on llvmpipe a fragment shader loads a uniform's values again for every 8 fragments, and the
// two maps' transforms of a typical OBJ material cost the G-buffer pass 2 ms (docs/performance.md).
vec2 mapUv(mat3x2 transform)
{
#if (MATERIAL_VARIANT & 2048) != 0
    return transform * vec3(uv, 1.0);
#else
    return uv;
#endif
}

const int kHasDiffuseMap = 1;
const int kHasSpecularMap = 2;
const int kHasNormalMap = 4;
const int kHasEmissiveMap = 8;
const int kHasMetallicRoughnessMap = 16;
const int kAlphaMask = 32;
const int kHasVertexColours = 64;
const int kHasSpecularTint = 128;
const int kFlipBackFaces = 256;
const int kHasOpacityMap = 1024;
const int kMetallicRoughnessModel = 4096;
const int kHasOcclusionMap = 8192;

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
    vec3 t = texture(normalMap, mapUv(normalUvTransform)).xyz * 2.0 - 1.0;
    t.xy *= materialNormalScale;
    vec3 mapped = T * t.x + B * t.y + N * t.z;
    return dot(mapped, mapped) > 0.0 ? normalize(mapped) : N;
}

// blinnPhongExponent, shared with the loaders (scene/Shininess.h).
#include "lib/shininess.glsl"

// The surface's coverage as meshSurface() found it: the opacity a blended (transparent)
// material is drawn with (shaders/transparent.frag); 1 for other variants.
float meshCoverage = 1.0;

// The fragment's view depth, interpolated: what the compact G-buffer stores.
float meshViewDepth()
{
    return viewDepth(worldPosition);
}

Surface meshSurface()
{
    Surface s;
    // On the pixel's ray at the interpolated depth, as every deferred pass rebuilds it.
    s.position = positionOnPixelRay(ivec2(gl_FragCoord.xy), meshViewDepth());
    // What multiplies the base colour (diffuse and specular tint) and the coverage.
    vec3 base = vec3(1.0);
    float coverage = 1.0;
#if (MATERIAL_VARIANT & (32 | 512)) != 0
    coverage = materialAlpha.x;
#endif
    // materialVariant is a constant, so the compiler drops the branches of absent maps and the
    // implicit derivatives of texture() are defined.
    if ((materialVariant & kHasVertexColours) != 0) {
#if (MATERIAL_VARIANT & 64) != 0
        base = vertexColour.rgb;
        coverage *= vertexColour.a;
#endif
    }
    if ((materialVariant & kHasDiffuseMap) != 0) {
        vec4 texel = texture(diffuseMap, mapUv(diffuseUvTransform));
        base *= texel.rgb;
        coverage *= texel.a;
    }
    if ((materialVariant & kHasOpacityMap) != 0)
        coverage *= texture(opacityMap, mapUv(opacityUvTransform)).r;
    // glTF alphaMode MASK: fully there at or above the cutoff, absent below it. The same test
    // cuts the shadow casters (shaders/shadow_depth.frag).
#if (MATERIAL_VARIANT & 32) != 0
    if (coverage < materialAlpha.y)
        discard;
#endif
    meshCoverage = coverage;
    s.diffuse = materialDiffuse * base;
    s.specular = materialSpecular;
    if ((materialVariant & kHasSpecularMap) != 0)
        s.specular *= texture(specularMap, mapUv(specularUvTransform)).rgb;
    if ((materialVariant & kHasSpecularTint) != 0)
        s.specular += materialSpecularTint * base;
    s.shininess = materialShininess;
    if ((materialVariant & (kHasMetallicRoughnessMap | kMetallicRoughnessModel)) == kHasMetallicRoughnessMap) {
        // The loader's mapping (scene/Scene.h Material) per texel: diffuse + tint is the base
        // colour, the factors times the texel are this point's metallic and roughness.
        vec2 roughnessMetallic = texture(specularMap, mapUv(specularUvTransform)).gb;
        float metallic = materialMetallicRoughness.x * roughnessMetallic.y;
        vec3 baseColour = (materialDiffuse + materialSpecularTint) * base;
        s.diffuse = baseColour * (1.0 - metallic);
        s.specular = vec3(0.04 * (1.0 - metallic)) + baseColour * metallic;
        s.shininess = blinnPhongExponent(materialMetallicRoughness.y * roughnessMetallic.x);
    }
    s.metallicRoughness = false;
    s.metallic = 0.0;
    s.roughness = 1.0;
    s.occlusion = 1.0;
    if ((materialVariant & kMetallicRoughnessModel) != 0) {
        // The metallic-roughness model (docs/lighting.md): the instance's diffuse is the base
        // colour and its specular (metallic, roughness, occlusion strength); the map's G and B
        // channels multiply roughness and metallic (glTF's metallicRoughnessTexture).
        vec3 baseColour = materialDiffuse * base;
        s.metallicRoughness = true;
        s.metallic = materialSpecular.x;
        s.roughness = materialSpecular.y;
        if ((materialVariant & kHasMetallicRoughnessMap) != 0) {
            vec2 roughnessMetallic = texture(specularMap, mapUv(specularUvTransform)).gb;
            s.metallic *= roughnessMetallic.y;
            s.roughness *= roughnessMetallic.x;
        }
        if ((materialVariant & kHasOcclusionMap) != 0)
            s.occlusion = 1.0 + materialSpecular.z * (texture(occlusionMap, mapUv(occlusionUvTransform)).r - 1.0);
        s.diffuse = baseColour * (1.0 - s.metallic);
        s.specular = mix(vec3(0.04), baseColour, s.metallic);
        s.shininess = 1.0;
    }
    s.normal = normalize(worldNormal);
    if ((materialVariant & kHasNormalMap) != 0)
        s.normal = normalMapped(s.normal);
    // glTF doubleSided: a back face is lit as the front face of the other side (the normal map's
    // whole frame reversed, which reverses its result).
    if ((materialVariant & kFlipBackFaces) != 0 && !gl_FrontFacing)
        s.normal = -s.normal;
    s.emissive = materialEmissive;
    if ((materialVariant & kHasEmissiveMap) != 0)
        s.emissive *= texture(emissiveMap, mapUv(emissiveUvTransform)).rgb;
    return withTermSwitches(s);
}
