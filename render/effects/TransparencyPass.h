// Transparent surfaces (AlphaMode::Blend), drawn after any technique's opaque lighting and
// before the display pass, the same way for every technique: the engines that light
// transparent surfaces under many lights (Filament, Godot 4, DOOM 2016, Frostbite) do it with
// a forward pass over a light grid. Here:
// - order: objects farthest first by the view depth of their world bounds' centre, each
//   object's back faces before its front faces (GpuScene::transparentLayersBackToFront). Exact
//   for convex objects that do not interpenetrate; docs/transparency.md says what it gets wrong;
// - depth: tested against the opaque surfaces' depth, never written;
// - lights: a cluster grid (render/culling/ClusterGrid.h) whose every tile spans the depths of the
//   transparent objects' bounds, every slice occupied, so a surface in front of, between or
//   beyond the opaque ones finds every light that may reach it (the clustered technique's
//   grid, fitted to the opaque surfaces, could not serve it); under forward, every light;
// - blending: premultiplied "over" (shaders/transparent.frag); each layer is drawn once per
//   light batch before the next layer, so that a layer is whole before one in front of it
//   covers it: with several batches the grid is rebuilt per layer and batch;
// - shadows: received from the shadow maps; transparent surfaces cast none; no SSAO.
#pragma once

#include <cstdint>
#include <memory>

#include "gl/Buffer.h"
#include "render/culling/ClusterGrid.h"
#include "render/culling/CullingVariant.h"
#include "render/frame/FramePasses.h"
#include "render/frame/FrameTargets.h"
#include "render/programs/LightingPrograms.h"

namespace manylights {

class GpuScene;

class TransparencyPass {
public:
    // For the techniques whose programs are made for `technique` (TechniqueOptions::shaders).
    explicit TransparencyPass(const TechniqueVariant& technique);
    const TechniqueVariant& technique() const { return technique_; }

    // Draws the scene's transparent objects over targets.lit (a no-op without any). `everyLight`:
    // loop over every light (the forward technique's reference) instead of the light grid.
    void run(const GpuScene& scene, FrameTargets& targets, FramePasses& passes, bool everyLight);

    // The (pixel, light) pairs the last run evaluated; counted only when the options counted
    // work.
    std::uint64_t lastLightEvaluations() const { return lastEvaluations_; }

private:
    TechniqueVariant technique_;
    std::unique_ptr<ClusterGrid> grid_;  // made on first use: forward needs none
    LightingProgram programs_;           // over the grid, or every light (ShaderVariant::everyLight)
    gl::Buffer evaluations_;
    std::uint64_t lastEvaluations_ = 0;
};

}  // namespace manylights
