// The scene on the GPU: one vertex and one index buffer for every mesh, the objects with
// their transforms and materials, the local lights in one storage buffer, and the per-frame
// uniform buffer.
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
#include "render/DriverProfile.h"
#include "render/LightBatches.h"
#include "render/LightingPrograms.h"
#include "render/TextureCache.h"
#include "scene/Scene.h"

namespace manylights {

// std430 layout of shaders/lib/lights.glsl: GpuLight.
struct GpuLight {
    glm::vec4 positionRadius;
    glm::vec4 intensityExponent;
    glm::vec4 attenuation;
    glm::vec4 spotAxisCosCutoff;
};
static_assert(sizeof(GpuLight) == 64);

// Packs a light for the GPU with its culling radius (lightRadius).
GpuLight packLight(const Light& light, float attenuationThreshold);

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

// std140 layout of shaders/lib/frame.glsl: Frame.
struct FrameUniforms {
    glm::mat4 viewProjection;
    glm::mat4 view;
    glm::vec4 eye;
    glm::vec4 viewAxis;
    glm::vec4 ambient;
    glm::vec4 directionalToLight;
    glm::vec4 directionalIntensity;
    glm::vec4 background;
    glm::uvec4 counts;
    glm::vec4 projection;  // tan(fovX / 2), tan(fovY / 2), near, far
    glm::vec4 viewport;    // width, height, 1 / width, 1 / height
    glm::vec4 time;        // x: the scene time in seconds (GpuScene::setTime)
    glm::vec4 terms;       // 1 or 0: ambient, diffuse, specular (the viewer's toggles), w unused
};

// The camera matrices for an image of the given size.
FrameUniforms makeFrameUniforms(const Scene& scene, const Camera& camera, int width, int height,
                                std::uint32_t lightCount);

class GpuScene {
public:
    // `lights` are the scene's lights as rendered (explicit and generated, see expandLights).
    // Loads every material's textures; throws manylights::Error for a broken one. `driver`: the
    // choices of the driver profile (render/DriverProfile.h), fixed for the scene's lifetime.
    GpuScene(const Scene& scene, const std::vector<Light>& lights, const DriverChoices& driver);

    // Binds the vertex array, the frame uniforms and the light buffer.
    void bind() const;
    // A run of draw items (consecutive in the instance buffer) drawn with one instanced call.
    struct DrawBatch {
        std::size_t firstItem;
        std::size_t itemCount;
    };

    // Draws every object (shaders/mesh.vert with lib/material.glsl): binds the instance buffer,
    // and per batch uses programFor(the material's variant) (mesh programs are compiled per
    // variant, render/LightingPrograms.h; programFor may set the program's own uniforms), sets
    // the batch's first record, the revolution uniforms, binds the material's maps (texture
    // units 6-8, 15) and culls back faces for single-sided materials (Sides::Front; culling is
    // off again afterwards). Items sharing a mesh range, variant and sides without maps or a
    // surface of revolution are one instanced draw (see batches()).
    using MeshProgramFor = std::function<const gl::Program&(MaterialVariant)>;
    void drawObjects(const MeshProgramFor& programFor) const;
    // The union of the drawn objects' world bounds.
    Bounds objectsWorldBounds() const;

    // Transparent objects (AlphaMode::Blend) are left out of drawObjects and of the depth-only
    // passes (they cast no shadows); the transparency pass draws them (render/TransparencyPass.h).
    bool hasTransparentObjects() const { return transparentBatches_ > 0; }
    // One draw of a transparent item: its batch (of one item), and whether it draws the item's
    // back faces (the far side of a closed mesh) or its front faces.
    struct TransparentLayer {
        std::size_t batch;
        bool backFaces;
    };
    // Farthest first by the view depth of the item's world bounds' centre; each item's back
    // faces before its front faces (a single-sided glTF material has front faces only).
    std::vector<TransparentLayer> transparentLayersBackToFront() const;
    // Draws a layer as drawObjects draws a batch, culling the other side's faces.
    void drawTransparentLayer(const TransparentLayer& layer, const MeshProgramFor& programFor) const;
    // The transparent items' world bounds (empty bounds left out).
    std::vector<Bounds> transparentWorldBounds() const;
    // Depth-only passes (shadow maps, shaders/shadow_depth.*): draws the items whose world
    // bounds pass `keep`, each run of kept items of a batch as one instanced draw, with
    // programFor(depthOnlyVariant(the material's variant)) (an alpha-masked caster's program
    // cuts its holes; the batch's diffuse map is bound for it); returns how many items were drawn.
    std::size_t drawObjectsDepthOnly(const MeshProgramFor& programFor,
                                     const std::function<bool(const Bounds&)>& keep) const;
    void setViewport(int width, int height);
    // The camera the frame uniforms are made for; the scene's own until set (the viewer moves it).
    void setCamera(const Camera& camera);
    const Camera& camera() const { return camera_; }
    // Poses the scene at time t (scene/Animation.h): object transforms, the light buffer (one
    // update) and the frame uniforms' time. A pure function of t: no state carries over.
    void setTime(double t);
    // Switches the ambient, diffuse and specular terms of the lighting on (1) or off (0).
    void setLightingTerms(const glm::vec3& terms);
    double time() const { return time_; }
    // Changes whenever the lights move, for passes that cache data derived from them.
    std::uint64_t lightsVersion() const { return lightsVersion_; }

    // The draw calls drawObjects makes (it makes them nearest first); their item counts sum to
    // drawItemCount().
    const std::vector<DrawBatch>& batches() const { return batches_; }
    // Draw items: one per object sub-mesh and per light marker (one instance record each).
    std::size_t drawItemCount() const { return draws_.size(); }
    // The unit sphere every light marker draws, scaled by the scene's lightMarkerRadius.
    static Mesh lightMarkerMesh();

    std::size_t lightCount() const { return lightCount_; }
    // The kinds of light the scene has and what the frame's shadowing reads, which the lighting
    // programs are specialised for.
    const LightingFeatures& lightingFeatures() const { return lightingFeatures_; }
    // Whether this frame reads a directional shadow map and the SSAO factor (the Renderer says,
    // before its technique runs; ShadowMaps sets the same in the shadowing uniforms).
    void setFrameShadowing(bool directionalShadow, bool ambientOcclusion)
    {
        lightingFeatures_.directionalShadow = directionalShadow;
        lightingFeatures_.ambientOcclusion = ambientOcclusion;
    }
    // The lights as posed at time() (their animations applied), and as the shaders get them.
    const std::vector<Light>& lights() const { return currentLights_; }
    const std::vector<GpuLight>& packedLights() const { return packedLights_; }
    const FrameUniforms& frameUniforms() const { return frame_; }
    const TextureCache& textures() const { return textures_; }
    const DriverChoices& driverChoices() const { return driver_; }
    // Binds lights [batch.first, batch.first + kLightsPerWindow) as the uniform block at
    // kLightWindowBinding; batch.first must be a multiple of kLightsPerWindow.
    void bindLightWindow(const LightBatch& batch) const;
    // Makes the light texels (render/LightBatches.h; bound by bind()) when `wanted` and the
    // driver has them for this many lights (lightTexelsSupported); drops them otherwise
    // (RendererDesc::lightTexels). They are wanted from the start.
    void setLightTexels(bool wanted);
    // Where a pass that reads any light by index reads them: the light texels where there are
    // some, else the storage buffer.
    LightSource indexedLightSource() const
    {
        return lightTexels_ ? LightSource::TexelBuffer : LightSource::StorageBuffer;
    }
    // Whether a pass whose pixels walk a batch of lights in order (deferred, forward; tiled and
    // clustered when the scene fits one window) reads the batch's uniform window
    // (bindLightWindow) rather than as by index. On a GPU, yes where the driver has the block
    // size: a read that every thread of a warp shares is a broadcast, what the vendors advise.
    // On a software rasteriser only without light texels, which it fetches faster than it
    // gathers from a uniform block, even at an index every lane shares (docs/performance.md:
    // LearnOpenGL's scene, 512 lights, deferred's lighting pass 620 ms from windows, 492 ms
    // from texels). The profile decides (DriverChoices::lightTexelsBeforeWindows).
    bool readsLightWindows() const
    {
        return lightWindowsSupported_ && (!driver_.lightTexelsBeforeWindows || !lightTexels_);
    }
    // Where such a pass reads its lights: the batch's uniform window where readsLightWindows(),
    // else as by index. Its batches are lightsPerBatch(source) lights.
    LightSource walkedLightSource() const
    {
        return readsLightWindows() ? LightSource::UniformWindow : indexedLightSource();
    }
    // Binds what reading `batch` from `source` needs beyond bind(): a uniform window's range.
    void bindLightSource(LightSource source, const LightBatch& batch) const
    {
        if (source == LightSource::UniformWindow)
            bindLightWindow(batch);
    }
    // Material textures' anisotropic filtering (TextureCache::setAnisotropy).
    void setAnisotropy(int requested) { textures_.setAnisotropy(requested); }
    const Scene& scene() const { return scene_; }
    // Changes whenever an object's transform or shape changes (cached shadow maps compare it);
    // setTime calls noteTransformsChanged() when anything moved.
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
        bool cullBackFaces;
        GLenum frontFace;
    };
    static FaceState faceStateOf(const DrawItem& draw);
    static void setFaceState(const FaceState& wanted, FaceState& current);
    void bindMaterial(const gl::Program& program, const Material& material, const MaterialMaps& maps) const;
    void setObjectUniforms(const gl::Program& program, const DrawItem& draw) const;
    void addLightMarkers(float radius);
    void groupDrawsIntoBatches();
    void poseDraws();
    void writeInstances();
    void drawInstances(const gl::Program& program, std::size_t firstItem, std::size_t itemCount) const;
    void packLights();
    // Opaque surfaces drawn nearest first let what lies behind them fail the depth test before
    // its fragments are shaded (docs/performance.md). Orders the items within each batch of
    // objects and the batches (frontToBack_) whenever the camera or the pose changes; the
    // caller then rewrites the instance records.
    void orderFrontToBack();

    // The frame uniforms of this camera and viewport, with terms_ and time_.
    void updateFrameUniforms();

    const Scene& scene_;
    DriverChoices driver_;
    Camera camera_;
    int viewportWidth_ = 1;
    int viewportHeight_ = 1;
    TextureCache textures_;
    LightingFeatures lightingFeatures_;
    std::vector<MaterialMaps> materialMaps_;  // per scene material
    MaterialMaps noMaps_;                     // light markers' materials have no textures
    std::vector<Light> restLights_;           // the lights at rest; their animations move them
    std::vector<Light> currentLights_;        // at time_
    std::vector<Material> markerMaterials_;
    double time_ = 0.0;
    glm::vec4 terms_{1.0f, 1.0f, 1.0f, 0.0f};
    std::uint64_t lightsVersion_ = 0;
    std::vector<std::vector<MeshRange>> meshRanges_;  // per mesh, its sub-meshes
    std::vector<DrawItem> draws_;                     // grouped by mesh range (groupDrawsIntoBatches)
    std::vector<DrawBatch> batches_;
    std::size_t transparentBatches_ = 0;
    std::vector<std::size_t> frontToBack_;  // indices into batches_, the order drawObjects draws
    std::vector<GpuInstance> instances_;    // draws_[i]'s record is instances_[i]
    std::vector<GpuLight> packedLights_;
    std::size_t lightCount_ = 0;
    std::uint64_t transformsVersion_ = 0;
    double posedTime_ = 0.0;  // the time the draws were last posed at
    FrameUniforms frame_{};
    gl::Buffer vertices_;
    gl::Buffer indices_;
    gl::VertexArray vertexArray_;
    gl::Buffer lightBuffer_;
    gl::BufferTexture lightTexels_;  // lightBuffer_ as texels, where the driver allows them
    bool lightWindowsSupported_ = lightWindowsSupported();
    gl::Buffer instanceBuffer_;
    gl::Buffer frameBuffer_;
};

}  // namespace manylights
