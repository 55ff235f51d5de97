// The light-volume techniques: each local light is shaded only over the pixels its bounding
// volume covers (docs/techniques.md explains both and why they are correct in every camera
// case).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "gl/Buffer.h"
#include "gl/Program.h"
#include "render/techniques/Technique.h"
#include "render/volumes/StencilBatches.h"
#include "render/volumes/VolumeDrawer.h"

namespace manylights {

// volumes: every light's volume drawn once, instanced per shape, back faces with the depth
// test reversed (GL_GEQUAL: the surface lies in front of the volume's far side) and depth
// clamping, so a camera inside a volume and volumes cut by the near or far plane still light
// every pixel they should.
class VolumesTechnique : public Technique {
public:
    explicit VolumesTechnique(const TechniqueOptions& options) : Technique(options), drawer_(options.shaders) {}
    std::string_view name() const override { return "volumes"; }
    void render(const GpuScene& scene, FrameTargets& targets, FramePasses& passes) override;

private:
    VolumeDrawer drawer_;
};

// stencil: per light, a stencil pass marks the pixels whose surface lies inside the volume,
// then the lighting pass shades only those (and clears their mark for the next light); lights
// whose volumes share no pixel on screen take both passes together, in batches
// (render/volumes/StencilBatches.h).
class StencilTechnique : public Technique {
public:
    explicit StencilTechnique(const TechniqueOptions& options);
    std::string_view name() const override { return "stencil"; }
    void render(const GpuScene& scene, FrameTargets& targets, FramePasses& passes) override;
    // gl_calls: the GL calls of the last frame's passes over the bounded lights (all but the
    // G-buffer and the global terms: gl/CallTally.h), gl_calls_per_light: those per light
    // with a volume, stencil_batches: the batches of the last frame.
    std::vector<TechniqueCounter> counters() const override;

private:
    VolumeDrawer drawer_;
    gl::Program stencilOnly_;  // the volume vertex shader and no fragment shader
    StencilBatcher batcher_;
    gl::Buffer batchOrder_;  // StencilBatches::order
    struct BatchesMadeFor {
        const GpuScene* scene = nullptr;
        std::uint64_t lightsVersion = 0;
        StencilBatchView view;
        bool operator==(const BatchesMadeFor&) const = default;
    };
    BatchesMadeFor batchesMadeFor_;
    std::uint64_t glCalls_ = 0;
    std::size_t volumeLights_ = 0;
    std::size_t batchCount_ = 0;
};

// The first passes of both: the G-buffer, then the global terms and the unbounded lights
// over every covered pixel.
void shadeGlobalTermsAndUnboundedLights(FramePasses& passes, VolumeDrawer& drawer);

}  // namespace manylights
