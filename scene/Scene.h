// Plain scene data: what a scene file (docs/scene-format.md) or the built-in default scene describes.
// No GL here: the render layer uploads this data, tests inspect it directly.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/Animation.h"
#include "scene/DisplaySettings.h"
#include "scene/Environment.h"
#include "scene/Mesh.h"
#include "scene/Revolution.h"

namespace manylights {

struct Camera {
    glm::vec3 eye{0.0f, 6.0f, 14.0f};
    glm::vec3 lookAt{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovYDegrees = 45.0f;
    float nearPlane = 0.1f;
    float farPlane = 200.0f;

    bool operator==(const Camera&) const = default;
};

// What keeps a camera from defining a view basis. One check for the scene file's camera and
// the command line's (--eye, --look-at, --up), so that both refuse the same cameras.
enum class CameraProblem {
    None,
    LookAtIsEye,        // no view direction
    DistanceOverflows,  // |look_at − eye| overflows a float: the basis would be NaN
    UpAlongView,        // up is zero or parallel to the view direction
};
CameraProblem cameraProblem(const Camera& camera);
// The problem in words, naming the scene file's keys ("look_at must differ from eye").
const char* describe(CameraProblem problem);

// A camera a model file defines (a glTF node's perspective camera), in scene space, under the
// name "<object>/<node name>": --camera NAME|INDEX renders through it (docs/cli.md).
struct NamedCamera {
    std::string name;
    Camera camera;
};

struct DirectionalLight {
    glm::vec3 direction{-1.0f, -2.0f, -1.0f};  // the direction light travels in
    glm::vec3 intensity{0.0f};
    bool shadows = false;
};

enum class LightType : std::uint8_t { Point, Spot };

// Which distance falloff a local light uses (docs/lighting.md).
enum class Falloff : std::uint8_t {
    Classic,  // 1 / (c + b·d + a·d²), cut where it drops below the attenuation threshold
    Range,    // 1/max(d, r/100)² − 1/r², exactly zero at r
};

struct ClassicAttenuation {
    float constant = 1.0f;
    float linear = 0.0f;
    float quadratic = 0.0f;
};

struct Light {
    LightType type = LightType::Point;
    std::string name;
    glm::vec3 position{0.0f};
    glm::vec3 intensity{1.0f};
    Falloff falloff = Falloff::Range;
    ClassicAttenuation attenuation;  // used when falloff == Classic
    float range = 1.0f;              // used when falloff == Range
    // Spot only.
    glm::vec3 direction{0.0f, -1.0f, 0.0f};
    float cutoffDegrees = 45.0f;  // half-angle, 0 < cutoff ≤ 180
    float exponent = 0.0f;
    // Motion over time around `position` (scene/Animation.h); none: the light stands still.
    std::optional<LightAnimation> animation{};
    // "casts_shadows": false opts the light out of --shadow-lights (all or a cap).
    bool castsShadows = true;
};

// A closed interval [lo, hi] from which a light set draws a value uniformly.
struct Interval {
    float lo = 0.0f;
    float hi = 0.0f;
};

// Lights generated deterministically from a seed (docs/scene-format.md `light_sets`).
struct LightSet {
    int count = 0;
    std::uint32_t seed = 0;
    LightType type = LightType::Point;
    glm::vec3 boxMin{0.0f};
    glm::vec3 boxMax{0.0f};
    Interval range{1.0f, 1.0f};
    Interval intensity{1.0f, 1.0f};
    Interval cutoffDegrees{20.0f, 45.0f};  // spot sets only
    Interval exponent{0.0f, 8.0f};         // spot sets only
    // When set, each light's range is multiplied by sqrt(rangeReferenceCount / count), count
    // being the set's count after --lights: the lights' total covered area stays that of
    // `range` at the reference count, so lights per pixel stay about constant in a sweep.
    std::optional<int> rangeReferenceCount;
    // Given to every generated light, light i's phase advanced by i times the golden angle.
    std::optional<LightAnimation> animation{};
    // "casts_shadows": false: every generated light opts out of --shadow-lights (Light::castsShadows).
    bool castsShadows = true;
};

// The texture slots of a material, in the order of Material::uvTransforms and of the shaders'
// uv transform array (shaders/lib/material.glsl). The metallic-roughness map takes the specular
// map's slot: a material has one or the other (a glTF material never has a specular map).
enum MaterialMapSlot : std::size_t {
    kDiffuseSlot,
    kSpecularSlot,
    kNormalSlot,
    kEmissiveSlot,
    kOpacitySlot,
    kOcclusionSlot,
    kMaterialMapSlots
};

// The reflection model that shades a material (docs/lighting.md): the classic Blinn-Phong of
// `diffuse`/`specular`/`shininess`, or glTF 2.0's metallic-roughness BRDF of `baseColor`,
// `metallicFactor` and `roughnessFactor`.
enum class ShadingModel : std::uint8_t { BlinnPhong, MetallicRoughness };

// Opaque ignores the coverage; Mask cuts the surface where it is below alphaCutoff; Blend draws
// the surface see-through, "over" what lies behind it with the coverage as its opacity
// (render/effects/TransparencyPass.h).
enum class AlphaMode : std::uint8_t { Opaque, Mask, Blend };

// How a map reads coordinates outside [0, 1] (glTF samplers' wrapS, wrapT), per axis.
enum class TextureWrap : std::uint8_t { Repeat, ClampToEdge, MirroredRepeat };
struct MapWrap {
    TextureWrap s = TextureWrap::Repeat;
    TextureWrap t = TextureWrap::Repeat;
};

// Which faces of a material's triangles are drawn, and with which normal.
enum class Sides : std::uint8_t {
    // Scene-file and OBJ materials: both faces, each lit with the mesh's normal as given. OBJ
    // files' winding is not reliable (their normals are), so no face is culled or flipped.
    BothWithMeshNormal,
    // glTF doubleSided false: back faces (clockwise on screen) are culled.
    Front,
    // glTF doubleSided true: both faces, a back face lit with the reversed normal.
    BothFlipped,
};

struct Material {
    std::string name;
    glm::vec3 diffuse{0.8f};
    glm::vec3 specular{0.0f};
    float shininess = 32.0f;
    glm::vec3 emissive{0.0f};
    // Texture paths, already resolved relative to the scene file; empty when absent.
    std::string diffuseMap;
    std::string specularMap;
    std::string normalMap;
    // Added for model files (docs/scene-format.md, "Model files"): the strength of the normal
    // map (glTF normalTexture.scale, MTL `-bm`), and an emissive map (glTF emissiveTexture,
    // MTL map_Ke) that multiplies `emissive`. A map path may also name an entry of
    // Scene::encodedImages (an image embedded in a glTF file) instead of a file.
    float normalScale = 1.0f;
    std::string emissiveMap;

    // glTF's metallic-roughness material (docs/scene-format.md, "Model files"), mapped to the
    // terms above as: diffuse = base · (1 − metallic), specular = 0.04 · (1 − metallic) and
    // specularTint = base · metallic. The tint is the part of the specular colour that is the
    // base colour: the diffuse map and vertex colours multiply it as they multiply `diffuse`,
    // and the surface's specular colour is specular + specularTint (zero for other materials).
    glm::vec3 specularTint{0.0f};
    // glTF metallicRoughnessTexture (roughness in G, metallic in B, linear): with it, the shader
    // redoes the mapping per texel from the factors times the texel (shaders/lib/material.glsl).
    std::string metallicRoughnessMap;
    float metallicFactor = 0.0f;
    float roughnessFactor = 1.0f;

    // The model that shades the material. A MetallicRoughness material is shaded by glTF's BRDF
    // from baseColor, metallicFactor and roughnessFactor (times the base colour and
    // metallic-roughness maps), and ignores diffuse, specular, specularTint and shininess.
    ShadingModel model = ShadingModel::BlinnPhong;
    glm::vec3 baseColor{1.0f};
    // glTF occlusionTexture (red channel, linear): ambient occlusion baked into the model, which
    // dims the ambient term by 1 + strength · (texel − 1). MetallicRoughness materials only.
    std::string occlusionMap;
    float occlusionStrength = 1.0f;

    // Texture-coordinate transforms per map slot (glTF KHR_texture_transform), in the mesh's uv
    // convention (origin at the bottom left): uv' = M · (u, v, 1). Identity unless a file says.
    std::array<glm::mat3, kMaterialMapSlots> uvTransforms{glm::mat3{1.0f}, glm::mat3{1.0f}, glm::mat3{1.0f},
                                                          glm::mat3{1.0f}, glm::mat3{1.0f}, glm::mat3{1.0f}};
    std::array<MapWrap, kMaterialMapSlots> wraps{};  // repeat unless a file's sampler says

    // Coverage: opacity (the scene file's `opacity`, glTF baseColorFactor's alpha, MTL `d`)
    // times the diffuse map's alpha times the vertex colour's alpha (AlphaMode says what it
    // does).
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    float opacity = 1.0f;
    // A map whose red channel multiplies the coverage (the scene file's `opacity_map`, MTL
    // `map_d`; a grey image reads the same in every channel). A material with one is
    // transparent (AlphaMode::Blend).
    std::string opacityMap;
    Sides sides = Sides::BothWithMeshNormal;
};

struct Object {
    std::string name;
    std::size_t mesh = 0;      // index into Scene::meshes
    std::size_t material = 0;  // index into Scene::materials
    glm::mat4 transform{1.0f};
    // True when the object names its material: it then replaces the mesh file's own materials
    // (docs/scene-format.md: a file's materials are used only when the object names none).
    bool materialOverridesMesh = true;
    // Motion over time; `transform` is the rest pose (scene/Animation.h).
    std::optional<ObjectAnimation> animation{};
    // A surface of revolution whose positions and normals the vertex shader computes from the
    // mesh's uvs and the time (scene/Revolution.h); the mesh is its grid (makeRevolutionGrid).
    std::optional<RevolutionProfile> revolution{};
};

// An image embedded in a model file (a glTF data: URI or buffer view), still encoded (PNG or
// JPEG bytes). A material's map path equal to `key` means this image; keys have the form
// "<model file>#images[<index>]", which no texture file on disk is looked up by.
struct EncodedImage {
    std::string key;
    std::string mimeType;  // as the file declares it; may be empty
    std::vector<unsigned char> bytes;
};

// Screen-space ambient occlusion of the ambient term (`ssao` in the scene file;
// docs/shadows.md). Off unless the scene asks for it: docs/lighting.md has no occlusion term.
struct AmbientOcclusion {
    bool enabled = false;
    float radius = 0.5f;    // world units: how far around a point occluders count
    float strength = 1.0f;  // ao = clamp(1 − strength · occluded fraction, 0, 1)
};

// Default from docs/lighting.md: a classic light is cut where A(d) · Imax falls to 1/256.
inline constexpr float kDefaultAttenuationThreshold = 1.0f / 256.0f;

struct Scene {
    std::string source;  // the scene file, or "<default scene>"
    // What loading forgave in model files, one line each (scene/Warnings.h): the commands
    // print them and count them in --stats.
    std::vector<std::string> warnings;
    Camera camera;
    glm::vec3 background{0.0f};
    glm::vec3 ambient{0.0f};
    std::optional<DirectionalLight> directional;
    AmbientOcclusion ssao;
    // "shadow_lights" in the scene file: N or "all" (kAllShadowLights, scene/ShadowSelection.h);
    // --shadow-lights overrides it. None: 0, only a directional light casts shadows.
    std::optional<int> shadowLights;
    // `environment` in the scene file: image-based light (docs/lighting.md, "The environment").
    std::optional<Environment> environment;
    DisplaySettings display;  // `display` in the scene file: how 8-bit outputs and the window show it
    float attenuationThreshold = kDefaultAttenuationThreshold;
    std::vector<Light> lights;         // explicit lights
    std::vector<NamedCamera> cameras;  // from model files, in the order they were loaded
    std::vector<LightSet> lightSets;   // generated lights (see expandLights)
    std::vector<Material> materials;
    std::vector<Mesh> meshes;
    std::vector<Object> objects;
    // When set, every rendered light also gets a small emissive sphere of this radius in its
    // own colour that follows it (drawn by the render layer as an ordinary object).
    std::optional<float> lightMarkerRadius;
    std::vector<EncodedImage> encodedImages;  // images embedded in model files (see EncodedImage)

    // World-space bounds of every object.
    Bounds worldBounds() const;
};

}  // namespace manylights
