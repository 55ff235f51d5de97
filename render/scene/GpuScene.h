// The scene on the GPU, as its three owners (each with its own file): the lights
// (render/scene/SceneLights.h), what is drawn (render/scene/DrawList.h) and the per-frame uniforms
// (render/scene/GpuFrame.h). GpuScene poses them together and answers the passes' questions that
// span them (the lighting programs' specialisation, the draw order from the camera).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "gl/Program.h"
#include "render/driver/DriverProfile.h"
#include "render/environment/EnvironmentLight.h"
#include "render/programs/LightBatches.h"
#include "render/programs/LightingPrograms.h"
#include "render/scene/DrawList.h"
#include "render/scene/GpuFrame.h"
#include "render/scene/SceneLights.h"
#include "render/scene/TextureCache.h"
#include "scene/Scene.h"

namespace manylights {

class GpuScene {
public:
    // `lights` are the scene's lights as rendered (explicit and generated, see expandLights):
    // the only route to the lights (the scene's own `lights` are not read). Loads every
    // material's textures; throws manylights::Error for a broken one. `driver`: the Renderer's
    // resolved driver choices (render/driver/DriverProfile.h), fixed for the scene's lifetime.
    // `scene` must outlive this.
    GpuScene(const Scene& scene, const std::vector<Light>& lights, const DriverChoices& driver);

    // The three owners, and the environment (none: a black one, EnvironmentLight()).
    const SceneLights& sceneLights() const { return lights_; }
    const DrawList& drawList() const { return draws_; }
    const GpuFrame& frame() const { return frame_; }
    const EnvironmentLight& environment() const { return environment_; }
    // The environment's intensity, rotation and background (the viewer's panel); nothing
    // without one.
    void setEnvironmentLook(const EnvironmentLook& look) { environment_.setLook(look); }

    // Binds the vertex array, the frame uniforms, the light buffer and the environment.
    void bind() const;
    using DrawBatch = DrawList::DrawBatch;
    using TransparentLayer = DrawList::TransparentLayer;
    using MeshProgramFor = DrawList::MeshProgramFor;

    // Draws every object (shaders/mesh.vert with lib/material.glsl): binds the instance buffer,
    // and per batch uses programFor(the material's variant) (mesh programs are compiled per
    // variant, render/programs/LightingPrograms.h; programFor may set the program's own uniforms), sets
    // the batch's first record, the revolution uniforms, binds the material's maps (texture
    // units 6-8, 15) and culls back faces for single-sided materials (Sides::Front; culling is
    // off again afterwards). Items sharing a mesh range, variant and sides without maps or a
    // surface of revolution are one instanced draw (see batches()).
    void drawObjects(const MeshProgramFor& programFor) const { draws_.drawObjects(programFor); }
    // The union of the drawn objects' world bounds.
    Bounds objectsWorldBounds() const { return draws_.objectsWorldBounds(); }

    // Transparent objects (AlphaMode::Blend) are left out of drawObjects and of the depth-only
    // passes (they cast no shadows); the transparency pass draws them (render/effects/TransparencyPass.h).
    bool hasTransparentObjects() const { return draws_.hasTransparentObjects(); }
    // Farthest first from this frame's camera (DrawList::transparentLayersBackToFront).
    std::vector<TransparentLayer> transparentLayersBackToFront() const;
    // Draws a layer as drawObjects draws a batch, culling the other side's faces.
    void drawTransparentLayer(const TransparentLayer& layer, const MeshProgramFor& programFor) const
    {
        draws_.drawTransparentLayer(layer, programFor);
    }
    // The transparent items' world bounds (empty bounds left out).
    std::vector<Bounds> transparentWorldBounds() const { return draws_.transparentWorldBounds(); }
    // Depth-only passes (shadow maps, shaders/shadow_depth.*): draws the items whose world
    // bounds pass `keep`, each run of kept items of a batch as one instanced draw, with
    // programFor(depthOnlyVariant(the material's variant)) (an alpha-masked caster's program
    // cuts its holes; the batch's diffuse map is bound for it); returns how many items were drawn.
    std::size_t drawObjectsDepthOnly(const MeshProgramFor& programFor,
                                     const std::function<bool(const Bounds&)>& keep) const
    {
        return draws_.drawObjectsDepthOnly(programFor, keep);
    }
    // The shadow casters and their draws into the shadow pages (DrawList::casters, drawCasterRuns).
    std::vector<DrawList::Caster> casters() const { return draws_.casters(); }
    std::size_t batchTriangles(std::size_t batch) const { return draws_.batchTriangles(batch); }
    void drawCasterRuns(const DrawList::MeshProgramFor& programFor, const std::vector<DrawList::CasterRun>& runs,
                        GLint baseLocation) const
    {
        draws_.drawCasterRuns(programFor, runs, baseLocation);
    }
    void setViewport(int width, int height);
    // The camera the frame uniforms are made for; the scene's own until set (the viewer moves it).
    void setCamera(const Camera& camera);
    const Camera& camera() const { return frame_.camera(); }
    // Poses the scene at time t (scene/Animation.h): object transforms, the frame uniforms'
    // time, and the lights (their buffer at the next applyLightPose). A pure function of t: no
    // state carries over.
    void setTime(double t);
    // Whether the lights' buffer has yet to be posed at time(), and poses it on the GPU
    // (SceneLights::applyPose): the frame's first pass.
    bool lightPosePending() const { return lights_.posePending(); }
    void applyLightPose() { lights_.applyPose(); }
    // Switches the ambient, diffuse and specular terms of the lighting on (1) or off (0).
    void setLightingTerms(const glm::vec3& terms) { frame_.setLightingTerms(terms); }
    double time() const { return frame_.time(); }
    // Changes whenever the lights move, for passes that cache data derived from them.
    std::uint64_t lightsVersion() const { return lights_.version(); }

    // The draw calls drawObjects makes (it makes them nearest first); their item counts sum to
    // drawItemCount().
    const std::vector<DrawBatch>& batches() const { return draws_.batches(); }
    // Draw items: one per object sub-mesh and per light marker (one instance record each).
    std::size_t drawItemCount() const { return draws_.itemCount(); }
    // The unit sphere every light marker draws, scaled by the scene's lightMarkerRadius.
    static Mesh lightMarkerMesh() { return DrawList::lightMarkerMesh(); }

    std::size_t lightCount() const { return lights_.count(); }
    // Whether a new time() moves some light (SceneLights::hasAnimatedLights).
    bool hasAnimatedLights() const { return lights_.hasAnimatedLights(); }
    // The GPU memory the lights hold (SceneLights::memoryBytes).
    std::size_t lightMemoryBytes() const { return lights_.memoryBytes(); }
    // The kinds of light the scene has and what the frame's shadowing reads, under the driver's
    // shader policy: what the lighting programs are specialised for.
    LightingFeatures lightingFeatures() const;
    // Whether this frame reads a directional shadow map and the SSAO factor (the Renderer says,
    // before its technique runs; ShadowMaps sets the same in the shadowing uniforms).
    void setFrameShadowing(bool directionalShadow, bool ambientOcclusion)
    {
        frame_.setShadowing(directionalShadow, ambientOcclusion);
    }
    // Light i as posed at time() (its animation applied), and the lights as the shaders get
    // them: the first call after a setTime that moved lights poses them on the CPU.
    Light light(std::size_t i) const { return lights_.posed(i); }
    const std::vector<GpuLight>& packedLights() const { return lights_.packed(); }
    const FrameUniforms& frameUniforms() const { return frame_.uniforms(); }
    const TextureCache& textures() const { return draws_.textures(); }
    // The light sources and windows (render/scene/SceneLights.h).
    void bindLightWindow(const LightBatch& batch) const { lights_.bindWindow(batch); }
    void setLightTexels(bool wanted) { lights_.setTexels(wanted); }
    LightSource indexedLightSource() const { return lights_.indexedSource(); }
    bool readsLightWindows() const { return lights_.readsWindows(); }
    LightSource walkedLightSource() const { return lights_.walkedSource(); }
    void bindLightSource(LightSource source, const LightBatch& batch) const { lights_.bindSource(source, batch); }
    // Material textures' anisotropic filtering (TextureCache::setAnisotropy).
    void setAnisotropy(int requested) { draws_.setAnisotropy(requested); }
    // The scene's objects, materials, camera and directional light (not its lights: lights()).
    const Scene& scene() const { return scene_; }
    // Changes whenever an object's transform or shape changes (cached shadow maps compare it);
    // setTime calls noteTransformsChanged() when anything moved.
    std::uint64_t transformsVersion() const { return draws_.transformsVersion(); }
    void noteTransformsChanged() { draws_.noteTransformsChanged(); }

private:
    // The draw order and the instance records follow the camera and the pose.
    void reorderDraws();

    const Scene& scene_;
    SceneLights lights_;
    DrawList draws_;
    GpuFrame frame_;
    EnvironmentLight environment_;
    LightingFeatures features_;  // without the frame's shadowing (frame_ has it)
};

}  // namespace manylights
