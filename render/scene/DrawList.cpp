#include "render/scene/DrawList.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <tuple>

#include <glm/gtc/matrix_transform.hpp>

#include "core/Error.h"
#include "gl/CallTally.h"
#include "render/programs/Bindings.h"
#include "render/programs/Locations.h"
#include "render/scene/SceneLights.h"
#include "scene/Meshes.h"
#include "scene/ShadowSelection.h"
#include "scene/Transform.h"

namespace manylights {

namespace {

// The object-space box a draw's vertices stay in: the mesh's own, or for a surface of
// revolution posed in the vertex shader, the largest its profile reaches at any time.
Bounds objectSpaceBounds(const Object& object, const Bounds& meshBounds)
{
    if (!object.revolution)
        return meshBounds;
    const RevolutionProfile& profile = *object.revolution;
    const float reach = profile.radius + profile.amplitude;
    Bounds bounds;
    bounds.extend({-reach, 0.0f, -reach});
    bounds.extend({reach, profile.height, reach});
    return bounds;
}
// lib/instances.glsl: the instance records and the uniform naming a draw's first record.
constexpr GLuint kInstancesBinding = bindings::INSTANCES_BUFFER_BINDING;
constexpr GLint kInstanceBase = locations::INSTANCE_BASE_LOCATION;
// A light marker is small on screen: a coarse unit sphere is round enough.
constexpr int kMarkerSlices = 16;
constexpr int kMarkerStacks = 8;

// Whether a draw item can share an instanced draw: material maps are bound per draw and a
// surface of revolution has its own uniforms, so such items are drawn one at a time.
bool instanceable(const Object* object, bool hasMaps) { return !hasMaps && !(object && object->revolution); }

bool isTransparent(const Material& material) { return material.alphaMode == AlphaMode::Blend; }

}  // namespace

DrawList::DrawList(const Scene& scene, const std::vector<Light>& lights, const DriverChoices& driver)
    : markerRadius_(scene.lightMarkerRadius),
      textures_(scene.encodedImages, driver.autoAnisotropy),
      vertexArray_("scene vertices")
{
    loadMeshes(scene);
    loadMaterialMaps(scene);
    std::vector<Bounds> meshBounds;
    for (const Mesh& mesh : scene.meshes)
        meshBounds.push_back(mesh.bounds());
    for (const Object& object : scene.objects)
        for (const MeshRange& range : meshRanges_[object.mesh]) {
            const std::size_t material =
                object.materialOverridesMesh || !range.material ? object.material : *range.material;
            draws_.push_back({object.transform, normalMatrix(object.transform), range, &scene.materials[material],
                              &materialMaps_[material], &object, std::nullopt,
                              objectSpaceBounds(object, meshBounds[object.mesh]), Bounds{}});
        }
    for (DrawItem& draw : draws_) {
        draw.worldBounds = transformedBounds(draw.meshBounds, draw.model);
        draw.variant = materialVariant(*draw.material, *draw.maps, draw.range);
        // Animations move and turn objects but never mirror them: the rest pose decides.
        draw.mirrored = glm::determinant(glm::mat3(draw.model)) < 0.0f;
    }
    if (markerRadius_)
        addLightMarkers(lights, *markerRadius_);
    groupDrawsIntoBatches();
    instances_.resize(draws_.size());
    instanceBuffer_ = gl::Buffer("instances", std::max<std::size_t>(1, instances_.size()) * sizeof(GpuInstance),
                                 nullptr, GL_DYNAMIC_STORAGE_BIT);
}

void DrawList::loadMeshes(const Scene& scene)
{
    std::vector<Vertex> allVertices;
    std::vector<std::uint32_t> allIndices;
    // The light markers' sphere is one more mesh after the scene's (made once, drawn per light).
    std::vector<const Mesh*> meshes;
    for (const Mesh& mesh : scene.meshes)
        meshes.push_back(&mesh);
    Mesh markerSphere;
    if (scene.lightMarkerRadius) {
        markerSphere = lightMarkerMesh();
        meshes.push_back(&markerSphere);
    }
    for (const Mesh* meshPointer : meshes) {
        const Mesh& mesh = *meshPointer;
        const auto baseVertex = static_cast<GLint>(allVertices.size());
        if (mesh.subMeshes.empty())
            meshRanges_.push_back({{baseVertex,
                                    allIndices.size(),
                                    static_cast<GLsizei>(mesh.indices.size()),
                                    {},
                                    mesh.hasVertexColours}});
        else {
            std::vector<MeshRange> ranges;
            for (const SubMesh& sub : mesh.subMeshes)
                ranges.push_back({baseVertex, allIndices.size() + sub.firstIndex, static_cast<GLsizei>(sub.indexCount),
                                  sub.material, mesh.hasVertexColours});
            meshRanges_.push_back(std::move(ranges));
        }
        allVertices.insert(allVertices.end(), mesh.vertices.begin(), mesh.vertices.end());
        allIndices.insert(allIndices.end(), mesh.indices.begin(), mesh.indices.end());
    }
    vertices_ = gl::Buffer::fromSpan<Vertex>("mesh vertices", allVertices, 0);
    indices_ = gl::Buffer::fromSpan<std::uint32_t>("mesh indices", allIndices, 0);
    vertexArray_.setVertexBuffer(0, vertices_, sizeof(Vertex));
    vertexArray_.setFloatAttribute(0, 0, 3, offsetof(Vertex, position));
    vertexArray_.setFloatAttribute(1, 0, 3, offsetof(Vertex, normal));
    vertexArray_.setFloatAttribute(2, 0, 2, offsetof(Vertex, uv));
    vertexArray_.setFloatAttribute(3, 0, 4, offsetof(Vertex, tangent));
    vertexArray_.setFloatAttribute(4, 0, 4, offsetof(Vertex, colour));
    vertexArray_.setIndexBuffer(indices_);
}

void DrawList::loadMaterialMaps(const Scene& scene)
{
    // Colour maps are sRGB-encoded 8-bit images; normal and specular maps hold data. A broken
    // file's message (naming the file) is completed with the material and key that use it.
    for (const Material& material : scene.materials) {
        const auto load = [&](const std::string& path, TextureColourSpace space,
                              const char* key) -> const gl::MipmappedTexture2D* {
            if (path.empty())
                return nullptr;
            try {
                return &textures_.get(path, space);
            } catch (const Error& e) {
                throw Error(std::string(e.what()) + " (" + key + " of material '" + material.name + "')");
            }
        };
        materialMaps_.push_back(
            {load(material.diffuseMap, TextureColourSpace::Srgb, "diffuse_map"),
             load(material.specularMap, TextureColourSpace::Linear, "specular_map"),
             load(material.normalMap, TextureColourSpace::Linear, "normal_map"),
             load(material.emissiveMap, TextureColourSpace::Srgb, "emissive map"),
             load(material.metallicRoughnessMap, TextureColourSpace::Linear, "metallic-roughness map"),
             load(material.opacityMap, TextureColourSpace::Linear, "opacity_map"),
             load(material.occlusionMap, TextureColourSpace::Linear, "occlusion_map")});
        // The two share the specular map's unit (scene/Scene.h MaterialMapSlot).
        ML_ASSERT(!materialMaps_.back().specular || !materialMaps_.back().metallicRoughness);
    }
}

SpecularExponents DrawList::specularExponents() const
{
    std::vector<const Material*> drawnMaterials;
    for (const DrawItem& draw : draws_)
        drawnMaterials.push_back(draw.material);
    return specularExponentsOf(drawnMaterials);
}

bool DrawList::drawsModel(ShadingModel model) const
{
    return std::ranges::any_of(draws_, [&](const DrawItem& draw) { return draw.material->model == model; });
}

Mesh DrawList::lightMarkerMesh() { return makeSphere(1.0f, kMarkerSlices, kMarkerStacks); }

void DrawList::addLightMarkers(const std::vector<Light>& lights, float radius)
{
    // Emissive in the light's own colour at full brightness (intensities are often well
    // below 1), and no diffuse or specular term: every technique shades it as forward does,
    // from the emissive term alone.
    markerMaterials_.reserve(lights.size());  // draws keep pointers into it
    const MeshRange sphere = meshRanges_.back().front();
    for (std::size_t i = 0; i < lights.size(); ++i) {
        Material material;
        material.name = "marker of " + lights[i].name;
        material.diffuse = glm::vec3{0.0f};
        material.specular = glm::vec3{0.0f};
        const glm::vec3 intensity = lights[i].intensity;
        const float brightest = std::max(intensity.r, std::max(intensity.g, intensity.b));
        material.emissive = brightest > 0.0f ? intensity / brightest : glm::vec3{0.0f};
        markerMaterials_.push_back(material);
        const glm::mat4 model = glm::scale(glm::mat4{1.0f}, glm::vec3{radius});
        draws_.push_back(
            {model, normalMatrix(model), sphere, &markerMaterials_.back(), &noMaps_, nullptr, i, Bounds{}, Bounds{}});
    }
}

void DrawList::groupDrawsIntoBatches()
{
    // Items of one mesh range next to each other (a stable sort), so that runs of them can be
    // instanced. The grouping is fixed here, once; poses change only the records. The draw
    // order is order()'s: nearest first, which decides which of two coplanar surfaces
    // wins a tie under GL_LESS; every technique draws in the same order, so they agree, and no
    // scene in the goldens has such a pair.
    const auto rangeKey = [](const DrawItem& draw) {
        return std::make_tuple(draw.range.baseVertex, draw.range.firstIndex, draw.range.indexCount);
    };
    std::stable_sort(draws_.begin(), draws_.end(),
                     [&](const DrawItem& a, const DrawItem& b) { return rangeKey(a) < rangeKey(b); });
    for (std::size_t i = 0; i < draws_.size(); ++i)
        draws_[i].groupedIndex = i;
    // Transparent items are drawn one at a time, in an order sorted per frame.
    const auto canShare = [](const DrawItem& draw) {
        return instanceable(draw.object, (draw.variant & kTextureBits) != 0) && !isTransparent(*draw.material);
    };
    // One program and one face state per draw call.
    const auto drawnAlike = [](const DrawItem& a, const DrawItem& b) {
        return a.variant == b.variant && a.material->sides == b.material->sides && a.mirrored == b.mirrored;
    };
    batches_.clear();
    for (std::size_t i = 0; i < draws_.size(); ++i) {
        if (!batches_.empty()) {
            const DrawItem& first = draws_[batches_.back().firstItem];
            if (canShare(first) && canShare(draws_[i]) && rangeKey(first) == rangeKey(draws_[i]) &&
                drawnAlike(first, draws_[i])) {
                ++batches_.back().itemCount;
                continue;
            }
        }
        batches_.push_back({i, 1});
    }
    transparentBatches_ =
        static_cast<std::size_t>(std::count_if(batches_.begin(), batches_.end(), [&](const DrawBatch& batch) {
            return isTransparent(*draws_[batch.firstItem].material);
        }));
}

void DrawList::order(const glm::vec3& eye, const glm::vec3& axis)
{
    // An item's key is the nearest view depth of its world bounds (a light marker's, of its
    // centre): the box's centre depth less its half extent along the view axis. Ties keep the
    // grouped order, so the order is a function of the scene, the pose and the camera.
    const auto key = [&](const DrawItem& draw) {
        const Bounds& bounds = draw.worldBounds;
        const glm::vec3 centre = bounds.empty() ? glm::vec3(draw.model[3]) : 0.5f * (bounds.min + bounds.max);
        const glm::vec3 halfExtent = bounds.empty() ? glm::vec3(0.0f) : 0.5f * (bounds.max - bounds.min);
        const float depth = glm::dot(centre - eye, axis) - glm::dot(glm::abs(axis), halfExtent);
        // Coordinates near the float limit can make the depth NaN, which would break the sort's
        // ordering (and with it std::sort): such an item goes last.
        return std::make_pair(std::isnan(depth) ? std::numeric_limits<float>::max() : depth, draw.groupedIndex);
    };
    std::vector<std::pair<float, std::size_t>> batchKeys(batches_.size());
    std::vector<std::pair<std::pair<float, std::size_t>, DrawItem>> keyed;  // each key computed once
    for (std::size_t b = 0; b < batches_.size(); ++b) {
        const auto first = draws_.begin() + static_cast<std::ptrdiff_t>(batches_[b].firstItem);
        const auto last = first + static_cast<std::ptrdiff_t>(batches_[b].itemCount);
        float nearest = std::numeric_limits<float>::max();
        if (first->markedLight) {
            // Light markers are small spheres that hide little; they stay in light order, so a
            // frame of a million lights only takes their nearest depth.
            for (auto item = first; item != last; ++item)
                nearest = std::min(nearest, key(*item).first);
        } else {
            // The instances of one draw are rasterised in order too: sorted nearest first.
            keyed.clear();
            for (auto item = first; item != last; ++item)
                keyed.emplace_back(key(*item), std::move(*item));
            std::sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& c) { return a.first < c.first; });
            std::transform(keyed.begin(), keyed.end(), first, [](auto& entry) { return std::move(entry.second); });
            nearest = keyed.front().first.first;
        }
        batchKeys[b] = {nearest, b};
    }
    std::sort(batchKeys.begin(), batchKeys.end());
    frontToBack_.resize(batchKeys.size());
    for (std::size_t k = 0; k < batchKeys.size(); ++k)
        frontToBack_[k] = batchKeys[k].second;
}

void DrawList::pose(double t, const SceneLights& lights)
{
    bool moved = false;
    const float markerRadius = markerRadius_.value_or(0.0f);
    for (DrawItem& draw : draws_) {
        if (draw.markedLight) {
            draw.model = glm::translate(glm::mat4{1.0f}, lights.posedPosition(*draw.markedLight));
            draw.model = glm::scale(draw.model, glm::vec3{markerRadius});
        } else if (draw.object->animation) {
            const glm::mat4 model = animatedTransform(draw.object->transform, draw.object->animation, t);
            if (model == draw.model)
                continue;
            draw.model = model;
            draw.worldBounds = transformedBounds(draw.meshBounds, draw.model);
            moved = true;
        } else {
            continue;
        }
        draw.normalMatrix = normalMatrix(draw.model);
    }
    // A dynamic surface of revolution changes shape with time even where it does not move.
    const bool reshaped = t != posedTime_ && std::any_of(draws_.begin(), draws_.end(), [](const DrawItem& draw) {
                              return draw.object && draw.object->revolution && draw.object->revolution->speed != 0.0f;
                          });
    posedTime_ = t;
    if (moved || reshaped)
        noteTransformsChanged();
}

void DrawList::writeInstances()
{
    for (std::size_t i = 0; i < draws_.size(); ++i) {
        const DrawItem& draw = draws_[i];
        GpuInstance& instance = instances_[i];
        instance.model = draw.model;
        for (int column = 0; column < 3; ++column)
            instance.normalMatrix[column] = glm::vec4(draw.normalMatrix[column], 0.0f);
        const Material& material = *draw.material;
        if (material.model == ShadingModel::MetallicRoughness) {
            // shaders/lib/material.glsl reads them as base colour and (metallic, roughness,
            // occlusion strength).
            instance.diffuse = glm::vec4(material.baseColor, material.opacity);
            instance.specularShininess =
                glm::vec4(material.metallicFactor, material.roughnessFactor, material.occlusionStrength, 1.0f);
        } else {
            instance.diffuse = glm::vec4(material.diffuse, material.opacity);
            instance.specularShininess = glm::vec4(material.specular, material.shininess);
        }
        instance.emissive = glm::vec4(material.emissive, material.alphaCutoff);
        instance.specularTint = glm::vec4(material.specularTint, 0.0f);
    }
    // One update for the whole frame.
    if (!instances_.empty())
        instanceBuffer_.update(0, instances_.size() * sizeof(GpuInstance), instances_.data());
}

void DrawList::bind() const { vertexArray_.bind(); }

void DrawList::setObjectUniforms(const gl::Program& program, const DrawItem& draw) const
{
    // shaders/lib/revolution.glsl, used by shaders/mesh.vert and shaders/shadow_depth.vert,
    // which position vertices the same way (the model matrix is in the instance record).
    enum : GLint {
        kRevolutionEnabled = locations::REVOLUTION_ENABLED_LOCATION,
        kRevolutionShape = locations::REVOLUTION_SHAPE_LOCATION,
        kRevolutionSpeed = locations::REVOLUTION_SPEED_LOCATION,
    };
    const RevolutionProfile* revolution = draw.object && draw.object->revolution ? &*draw.object->revolution : nullptr;
    program.set(kRevolutionEnabled, revolution ? 1 : 0);
    if (revolution) {
        program.set(kRevolutionShape,
                    glm::vec4(revolution->radius, revolution->height, revolution->amplitude, revolution->waves));
        program.set(kRevolutionSpeed, revolution->speed);
    }
}

void DrawList::drawInstances(const gl::Program& program, std::size_t firstItem, std::size_t itemCount) const
{
    // The base goes in a uniform and the draw's own base instance stays 0: gl_InstanceID does
    // not include it, and gl_BaseInstance is not core GL 4.5 (lib/instances.glsl).
    program.set(kInstanceBase, static_cast<int>(firstItem));
    const MeshRange& range = draws_[firstItem].range;
    glDrawElementsInstancedBaseVertex(GL_TRIANGLES, range.indexCount, GL_UNSIGNED_INT,
                                      reinterpret_cast<const void*>(range.firstIndex * sizeof(std::uint32_t)),
                                      static_cast<GLsizei>(itemCount), range.baseVertex);
}

void DrawList::drawObjects(const MeshProgramFor& programFor) const
{
    instanceBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, kInstancesBinding);
    const gl::Program* current = nullptr;
    // Face state is changed only where it differs: on llvmpipe every state change revalidates
    // the pipeline at the next draw. The pass's record set it (no culling, counter-clockwise
    // unless the record says otherwise) and restores it when the pass ends.
    std::optional<FaceState> faces;
    for (const std::size_t index : frontToBack_) {
        const DrawBatch& batch = batches_[index];
        // Every item of a batch of several has the same variant and face state, no maps and no
        // revolution: the first item's uniforms hold for all of them.
        const DrawItem& first = draws_[batch.firstItem];
        if (isTransparent(*first.material))
            continue;
        const gl::Program& program = programFor(first.variant);
        if (&program != current) {
            program.use();
            current = &program;
        }
        setObjectUniforms(program, first);
        bindMaterial(program, *first.material, *first.maps);
        const FaceState wanted = faceStateOf(first);
        if (wanted != faces) {
            applyFaceState(wanted.cull, wanted.frontFace);
            faces = wanted;
        }
        drawInstances(program, batch.firstItem, batch.itemCount);
    }
}

std::vector<DrawList::TransparentLayer> DrawList::transparentLayersBackToFront(const glm::vec3& eye,
                                                                               const glm::vec3& axis) const
{
    std::vector<std::pair<float, std::size_t>> keyed;  // (view depth, batch)
    for (std::size_t b = 0; b < batches_.size(); ++b) {
        const DrawItem& item = draws_[batches_[b].firstItem];
        if (!isTransparent(*item.material) || item.worldBounds.empty())
            continue;
        const glm::vec3 centre = 0.5f * (item.worldBounds.min + item.worldBounds.max);
        const float depth = glm::dot(centre - eye, axis);
        keyed.emplace_back(std::isnan(depth) ? std::numeric_limits<float>::max() : depth, b);
    }
    // Farthest first; equal depths in the grouped order, so the order is a function of the
    // scene, the pose and the camera.
    std::sort(keyed.begin(), keyed.end(), [&](const auto& a, const auto& c) {
        return a.first != c.first ? a.first > c.first
                                  : draws_[batches_[a.second].firstItem].groupedIndex <
                                        draws_[batches_[c.second].firstItem].groupedIndex;
    });
    std::vector<TransparentLayer> layers;
    for (const auto& [depth, batch] : keyed) {
        if (draws_[batches_[batch].firstItem].material->sides != Sides::Front)
            layers.push_back({batch, true});
        layers.push_back({batch, false});
    }
    return layers;
}

void DrawList::drawTransparentLayer(const TransparentLayer& layer, const MeshProgramFor& programFor) const
{
    instanceBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, kInstancesBinding);
    const DrawBatch& batch = batches_[layer.batch];
    const DrawItem& item = draws_[batch.firstItem];
    const gl::Program& program = programFor(item.variant);
    program.use();
    setObjectUniforms(program, item);
    bindMaterial(program, *item.material, *item.maps);
    // A transparent mesh's winding decides its layers, whatever its material's sides. The
    // pass's record restores the faces' state when the pass ends.
    applyFaceState(layer.backFaces ? Cull::FrontFaces : Cull::BackFaces,
                   item.mirrored ? Winding::Clockwise : Winding::CounterClockwise);
    drawInstances(program, batch.firstItem, batch.itemCount);
}

std::vector<Bounds> DrawList::transparentWorldBounds() const
{
    std::vector<Bounds> bounds;
    for (const DrawBatch& batch : batches_) {
        const DrawItem& item = draws_[batch.firstItem];
        if (isTransparent(*item.material) && !item.worldBounds.empty())
            bounds.push_back(item.worldBounds);
    }
    return bounds;
}

MaterialVariant DrawList::materialVariant(const Material& material, const MaterialMaps& maps, const MeshRange& range)
{
    return static_cast<MaterialVariant>(
        (maps.diffuse ? kDiffuseMapBit : 0) | (maps.specular ? kSpecularMapBit : 0) |
        (maps.normal ? kNormalMapBit : 0) | (maps.emissive ? kEmissiveMapBit : 0) |
        (maps.metallicRoughness ? kMetallicRoughnessMapBit : 0) | (maps.opacity ? kOpacityMapBit : 0) |
        (material.alphaMode == AlphaMode::Mask ? kAlphaMaskBit : 0) | (range.vertexColours ? kVertexColoursBit : 0) |
        // The metallic-roughness map's per-texel mapping to Blinn-Phong reads the base colour as
        // diffuse + tint.
        (material.model == ShadingModel::BlinnPhong &&
                 (material.specularTint != glm::vec3{0.0f} || maps.metallicRoughness)
             ? kSpecularTintBit
             : 0) |
        (material.sides == Sides::BothFlipped ? kFlipBackFacesBit : 0) | (isTransparent(material) ? kBlendBit : 0) |
        (std::ranges::any_of(material.uvTransforms, [](const glm::mat3& m) { return m != glm::mat3{1.0f}; })
             ? kUvTransformsBit
             : 0) |
        (material.model == ShadingModel::MetallicRoughness ? kMetallicRoughnessModelBit : 0) |
        (maps.occlusion ? kOcclusionMapBit : 0));
}

DrawList::FaceState DrawList::faceStateOf(const DrawItem& draw)
{
    // gl_FrontFacing (which Sides::BothFlipped lights by) follows the winding too.
    return {draw.material->sides == Sides::Front ? Cull::BackFaces : Cull::None,
            draw.mirrored && draw.material->sides != Sides::BothWithMeshNormal ? Winding::Clockwise
                                                                               : Winding::CounterClockwise};
}

void DrawList::bindMaterial(const gl::Program& program, const Material& material, const MaterialMaps& maps) const
{
    // Locations and units of shaders/lib/material.glsl (its constants come from the instance
    // record, DrawList::writeInstances; which maps it samples, from the program: materialVariant).
    // A map's uniforms are inactive, so left unset, without the map.
    enum : GLint {
        kNormalScale = locations::MATERIAL_NORMAL_SCALE_LOCATION,
        kMetallicRoughness = locations::MATERIAL_METALLIC_ROUGHNESS_LOCATION,
        kDiffuseUvTransform = locations::DIFFUSE_UV_TRANSFORM_LOCATION,
        kSpecularUvTransform = locations::SPECULAR_UV_TRANSFORM_LOCATION,
        kNormalUvTransform = locations::NORMAL_UV_TRANSFORM_LOCATION,
        kEmissiveUvTransform = locations::EMISSIVE_UV_TRANSFORM_LOCATION,
        kOpacityUvTransform = locations::OPACITY_UV_TRANSFORM_LOCATION,
        kOcclusionUvTransform = locations::OCCLUSION_UV_TRANSFORM_LOCATION,
    };
    constexpr GLuint kDiffuseUnit = bindings::DIFFUSE_MAP_UNIT;
    constexpr GLuint kSpecularUnit = bindings::SPECULAR_MAP_UNIT;
    constexpr GLuint kNormalUnit = bindings::NORMAL_MAP_UNIT;
    constexpr GLuint kEmissiveUnit = bindings::EMISSIVE_MAP_UNIT;
    constexpr GLuint kOpacityUnit = bindings::OPACITY_MAP_UNIT;
    constexpr GLuint kOcclusionUnit = bindings::OCCLUSION_MAP_UNIT;
    const auto glWrap = [](TextureWrap wrap) -> GLenum {
        switch (wrap) {
        case TextureWrap::ClampToEdge: return GL_CLAMP_TO_EDGE;
        case TextureWrap::MirroredRepeat: return GL_MIRRORED_REPEAT;
        case TextureWrap::Repeat: break;
        }
        return GL_REPEAT;
    };
    const auto bind = [&](const gl::MipmappedTexture2D* map, GLuint unit, GLint transformLocation,
                          MaterialMapSlot slot) {
        if (!map)
            return false;
        map->bindUnit(unit);
        // Wrapping belongs to the material's reference, not to the image the cache shares.
        map->setWrap(glWrap(material.wraps[slot].s), glWrap(material.wraps[slot].t));
        program.set(transformLocation, glm::mat3x2(material.uvTransforms[slot]));
        return true;
    };
    bind(maps.diffuse, kDiffuseUnit, kDiffuseUvTransform, kDiffuseSlot);
    bind(maps.specular, kSpecularUnit, kSpecularUvTransform, kSpecularSlot);
    // The metallic-roughness model reads its factors from the instance record; the mapping to
    // Blinn-Phong from this uniform.
    if (bind(maps.metallicRoughness, kSpecularUnit, kSpecularUvTransform, kSpecularSlot) &&
        material.model == ShadingModel::BlinnPhong)
        program.set(kMetallicRoughness, glm::vec2(material.metallicFactor, material.roughnessFactor));
    if (bind(maps.normal, kNormalUnit, kNormalUvTransform, kNormalSlot))
        program.set(kNormalScale, material.normalScale);
    bind(maps.emissive, kEmissiveUnit, kEmissiveUvTransform, kEmissiveSlot);
    bind(maps.opacity, kOpacityUnit, kOpacityUvTransform, kOpacitySlot);
    bind(maps.occlusion, kOcclusionUnit, kOcclusionUvTransform, kOcclusionSlot);
}

Bounds DrawList::objectsWorldBounds() const
{
    Bounds all;
    for (const DrawItem& draw : draws_)
        if (!draw.worldBounds.empty()) {
            all.extend(draw.worldBounds.min);
            all.extend(draw.worldBounds.max);
        }
    return all;
}

const gl::Program& DrawList::useDepthOnlyProgram(const MeshProgramFor& programFor, const DrawItem& first,
                                                 const gl::Program*& current) const
{
    const MaterialVariant variant = depthOnlyVariant(first.variant);
    const gl::Program& program = programFor(variant);
    if (&program != current) {
        program.use();
        current = &program;
    }
    setObjectUniforms(program, first);
    if ((variant & kDiffuseMapBit) != 0) {
        MaterialMaps diffuseOnly;
        diffuseOnly.diffuse = first.maps->diffuse;
        bindMaterial(program, *first.material, diffuseOnly);
    }
    return program;
}

bool DrawList::castsShadows(const DrawItem& item)
{
    // Transparent surfaces cast no shadows (docs/transparency.md); light markers have no bounds.
    return !item.worldBounds.empty() && !isTransparent(*item.material);
}

std::size_t DrawList::drawObjectsDepthOnly(const MeshProgramFor& programFor,
                                           const std::function<bool(const Bounds&)>& keep) const
{
    instanceBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, kInstancesBinding);
    std::size_t drawn = 0;
    const gl::Program* current = nullptr;
    for (const DrawBatch& batch : batches_) {
        const gl::Program& program = useDepthOnlyProgram(programFor, draws_[batch.firstItem], current);
        // Culling splits a batch into runs of kept items, each one instanced draw.
        const std::size_t end = batch.firstItem + batch.itemCount;
        std::optional<std::size_t> runStart;
        for (std::size_t i = batch.firstItem; i <= end; ++i) {
            const bool kept = i < end && castsShadows(draws_[i]) && keep(draws_[i].worldBounds);
            if (kept && !runStart)
                runStart = i;
            if (!kept && runStart) {
                drawInstances(program, *runStart, i - *runStart);
                drawn += i - *runStart;
                runStart.reset();
            }
        }
    }
    return drawn;
}

std::vector<DrawList::Caster> DrawList::casters() const
{
    std::vector<Caster> result;
    for (std::size_t batch = 0; batch < batches_.size(); ++batch) {
        const DrawBatch& run = batches_[batch];
        for (std::size_t i = run.firstItem; i < run.firstItem + run.itemCount; ++i)
            if (castsShadows(draws_[i]))
                result.push_back({i, batch, draws_[i].groupedIndex, draws_[i].worldBounds});
    }
    return result;
}

void DrawList::drawCasterRuns(const MeshProgramFor& programFor, const std::vector<CasterRun>& runs,
                              GLint baseLocation) const
{
    instanceBuffer_.bindBase(GL_SHADER_STORAGE_BUFFER, kInstancesBinding);
    const gl::Program* current = nullptr;
    for (const CasterRun& run : runs) {
        const DrawItem& first = draws_[batches_[run.batch].firstItem];
        const gl::Program& program = useDepthOnlyProgram(programFor, first, current);
        program.set(baseLocation, static_cast<int>(run.first));
        const MeshRange& range = first.range;
        gl::counted(glDrawElementsInstancedBaseVertex, GL_TRIANGLES, range.indexCount, GL_UNSIGNED_INT,
                    reinterpret_cast<const void*>(range.firstIndex * sizeof(std::uint32_t)),
                    static_cast<GLsizei>(run.count), range.baseVertex);
    }
}

}  // namespace manylights
