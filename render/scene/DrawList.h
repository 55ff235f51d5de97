// What the scene draws: one vertex and one index buffer for every mesh, the draw items (object
// sub-meshes and light markers) with their transforms and materials, grouped into instanced
// batches and ordered nearest first, and the per-item instance records
// (shaders/lib/instances.glsl).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "gl/Buffer.h"
#include "gl/Program.h"
#include "gl/Texture.h"
#include "gl/VertexArray.h"
#include "render/driver/DriverProfile.h"
#include "render/programs/LightingPrograms.h"
#include "render/programs/PipelineState.h"
#include "render/scene/TextureCache.h"
#include "scene/Scene.h"

namespace manylights {

class SceneLights;

// std430 layout of shaders/lib/instances.glsl: Instance. One per draw item, written each frame.
struct GpuInstance {
    glm::mat4 model;
    glm::vec4 normalMatrix[3];  // columns; w unused
    glm::vec4 diffuse;
    glm::vec4 specularShininess;
    glm::vec4 emissive;
    glm::vec4 specularTint;
};
static_assert(sizeof(GpuInstance) == 176);

class DrawList {
public:
    // The scene's objects, and a marker for each of `lights` (at rest) where the scene has
    // lightMarkerRadius. Loads every material's textures; throws manylights::Error for a broken
    // one. `scene` must outlive the list (items point at its objects and materials).
    DrawList(const Scene& scene, const std::vector<Light>& lights, const DriverChoices& driver);

    // A run of draw items (consecutive in the instance buffer) drawn with one instanced call.
    struct DrawBatch {
        std::size_t firstItem;
        std::size_t itemCount;
    };
    using MeshProgramFor = std::function<const gl::Program&(MaterialVariant)>;

    // Binds the vertex array.
    void bind() const;
    // Poses the items at time t (scene/Animation.h): object transforms, and light markers at
    // `lights` posed at t (asked for only where there are markers: posing the lights on the
    // CPU is work a scene without markers does not need). Call order() and writeInstances() after.
    void pose(double t, const SceneLights& lights);
    // Opaque surfaces drawn nearest first let what lies behind them fail the depth test before
    // its fragments are shaded (docs/performance.md). Orders the items within each batch of
    // objects and the batches by their view depth from `eye` along `viewAxis`; the caller then
    // rewrites the instance records (writeInstances).
    void order(const glm::vec3& eye, const glm::vec3& viewAxis);
    // Writes every item's instance record, in one buffer update.
    void writeInstances();

    // Draws every opaque object; see GpuScene::drawObjects.
    void drawObjects(const MeshProgramFor& programFor) const;
    // The union of the drawn objects' world bounds.
    Bounds objectsWorldBounds() const;
    bool hasTransparentObjects() const { return transparentBatches_ > 0; }
    // One draw of a transparent item: its batch (of one item), and whether it draws the item's
    // back faces (the far side of a closed mesh) or its front faces.
    struct TransparentLayer {
        std::size_t batch;
        bool backFaces;
    };
    // Farthest first from `eye` along `viewAxis` by the view depth of the item's world bounds'
    // centre; each item's back faces before its front faces (a single-sided glTF material has
    // front faces only).
    std::vector<TransparentLayer> transparentLayersBackToFront(const glm::vec3& eye, const glm::vec3& viewAxis) const;
    // Draws a layer as drawObjects draws a batch, culling the other side's faces.
    void drawTransparentLayer(const TransparentLayer& layer, const MeshProgramFor& programFor) const;
    // The transparent items' world bounds (empty bounds left out).
    std::vector<Bounds> transparentWorldBounds() const;
    // Depth-only passes; see GpuScene::drawObjectsDepthOnly.
    std::size_t drawObjectsDepthOnly(const MeshProgramFor& programFor,
                                     const std::function<bool(const Bounds&)>& keep) const;

    // A shadow caster (opaque, with bounds; render/shadows/ShadowPool.h): its item's index (its
    // instance record's, valid until the next order()), its batch, an identity that stays
    // with it from frame to frame, and its world bounds.
    struct Caster {
        std::size_t item;
        std::size_t batch;
        std::size_t identity;
        Bounds worldBounds;
    };
    std::vector<Caster> casters() const;
    // The triangles one instance of a batch's mesh draws.
    std::size_t batchTriangles(std::size_t batch) const
    {
        return static_cast<std::size_t>(draws_[batches_[batch].firstItem].range.indexCount) / 3;
    }
    // Instances of one batch's mesh whose (item, face part) pairs are `count` from `first` of
    // the pairs buffer shaders/shadow_page.vert reads, its base set at `baseLocation`.
    struct CasterRun {
        std::size_t batch;
        std::size_t first;
        std::size_t count;
    };
    // Draws each run as one instanced draw with programFor(depthOnlyVariant(...)), as
    // drawObjectsDepthOnly draws a batch.
    void drawCasterRuns(const MeshProgramFor& programFor, const std::vector<CasterRun>& runs, GLint baseLocation) const;

    // The draw calls drawObjects makes (it makes them nearest first); their item counts sum to
    // itemCount().
    const std::vector<DrawBatch>& batches() const { return batches_; }
    // Draw items: one per object sub-mesh and per light marker (one instance record each).
    std::size_t itemCount() const { return draws_.size(); }
    // The unit sphere every light marker draws, scaled by the scene's lightMarkerRadius.
    static Mesh lightMarkerMesh();
    // The shininesses the drawn materials raise N·H to (specularExponentsOf).
    SpecularExponents specularExponents() const;
    // Whether any drawn item (light markers included) is shaded by `model`.
    bool drawsModel(ShadingModel model) const;

    const TextureCache& textures() const { return textures_; }
    // Material textures' anisotropic filtering (TextureCache::setAnisotropy).
    void setAnisotropy(int requested) { textures_.setAnisotropy(requested); }
    // Changes whenever an object's transform or shape changes (cached shadow maps compare it);
    // pose() calls noteTransformsChanged() when anything moved.
    std::uint64_t transformsVersion() const { return transformsVersion_; }
    void noteTransformsChanged() { ++transformsVersion_; }

private:
    // One sub-mesh's place in the shared buffers.
    struct MeshRange {
        GLint baseVertex;
        std::size_t firstIndex;
        GLsizei indexCount;
        std::optional<std::size_t> material;  // the mesh file's own, if any
        bool vertexColours = false;           // the mesh's Mesh::hasVertexColours
    };
    // A material's maps in the texture cache; null where the material has none.
    struct MaterialMaps {
        const gl::MipmappedTexture2D* diffuse = nullptr;
        const gl::MipmappedTexture2D* specular = nullptr;
        const gl::MipmappedTexture2D* normal = nullptr;
        const gl::MipmappedTexture2D* emissive = nullptr;
        const gl::MipmappedTexture2D* metallicRoughness = nullptr;  // in the specular map's unit
        const gl::MipmappedTexture2D* opacity = nullptr;
        const gl::MipmappedTexture2D* occlusion = nullptr;
    };
    struct DrawItem {
        glm::mat4 model;
        glm::mat3 normalMatrix;
        MeshRange range;
        const Material* material;
        const MaterialMaps* maps;                // the material's textures
        const Object* object;                    // the scene's object; none for a light marker
        std::optional<std::size_t> markedLight;  // the light a marker follows
        Bounds meshBounds;                       // object space; empty for light markers, which cast no shadows
        Bounds worldBounds;                      // for culling depth-only passes against a light's volume
        std::size_t groupedIndex = 0;            // place after groupDrawsIntoBatches; breaks draw-order ties
        MaterialVariant variant = 0;             // what the mesh program reads (materialVariant)
        // A transform with a negative determinant mirrors the mesh, which reverses its winding:
        // the front faces of a mirrored glTF mesh are clockwise (glTF 2.0, "Meshes").
        bool mirrored = false;
    };

    static MaterialVariant materialVariant(const Material& material, const MaterialMaps& maps, const MeshRange& range);
    // Culling and front-face winding for a batch's material and mirroring.
    struct FaceState {
        Cull cull;
        Winding frontFace;
        friend bool operator==(const FaceState&, const FaceState&) = default;
    };
    static FaceState faceStateOf(const DrawItem& draw);
    void loadMeshes(const Scene& scene);
    void loadMaterialMaps(const Scene& scene);
    void bindMaterial(const gl::Program& program, const Material& material, const MaterialMaps& maps) const;
    void setObjectUniforms(const gl::Program& program, const DrawItem& draw) const;
    // A depth-only pass's program for a batch whose first item is `first` (the shadow maps' and
    // pages' casters): made current where `current` is another, with the batch's object
    // uniforms and, for an alpha-masked caster, its diffuse map.
    const gl::Program& useDepthOnlyProgram(const MeshProgramFor& programFor, const DrawItem& first,
                                           const gl::Program*& current) const;
    // Whether an item casts shadows: opaque, with bounds (light markers have none).
    static bool castsShadows(const DrawItem& item);
    void addLightMarkers(const std::vector<Light>& lights, float radius);
    void groupDrawsIntoBatches();
    void drawInstances(const gl::Program& program, std::size_t firstItem, std::size_t itemCount) const;

    std::optional<float> markerRadius_;  // the scene's lightMarkerRadius
    TextureCache textures_;
    std::vector<MaterialMaps> materialMaps_;  // per scene material
    MaterialMaps noMaps_;                     // light markers' materials have no textures
    std::vector<Material> markerMaterials_;
    std::vector<std::vector<MeshRange>> meshRanges_;  // per mesh, its sub-meshes
    std::vector<DrawItem> draws_;                     // grouped by mesh range (groupDrawsIntoBatches)
    std::vector<DrawBatch> batches_;
    std::size_t transparentBatches_ = 0;
    std::vector<std::size_t> frontToBack_;  // indices into batches_, the order drawObjects draws
    std::vector<GpuInstance> instances_;    // draws_[i]'s record is instances_[i]
    std::uint64_t transformsVersion_ = 0;
    double posedTime_ = 0.0;  // the time the items were last posed at
    gl::Buffer vertices_;
    gl::Buffer indices_;
    gl::VertexArray vertexArray_;
    gl::Buffer instanceBuffer_;
};

}  // namespace manylights
