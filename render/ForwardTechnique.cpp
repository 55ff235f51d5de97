// forward: the reference. Every fragment of every object loops over every light.
#include "render/ForwardTechnique.h"

#include "render/FramePasses.h"
#include "render/GpuScene.h"
#include "render/LightBatches.h"

namespace manylights {

ForwardTechnique::ForwardTechnique(const TechniqueOptions& options)
    : Technique(options),
      program_("forward", {{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "forward.frag"}},
               shaderDefines(options))
{
}

void ForwardTechnique::render(const GpuScene& scene, FrameTargets& targets, FramePasses& passes)
{
    // One draw of the objects per light batch. The later ones add their batch's light to the
    // fragments the first one left visible: the same program draws the same triangles, so the
    // depth test GL_EQUAL passes exactly those (GL's invariance rule).
    // Forward reads no G-buffer, but its ambient term reads SSAO's occlusion, which counts as
    // part of it (Resource::GBuffer): the passes wait for SSAO's image stores.
    constexpr Pass kFirstBatch{.name = "forward", .target = Resource::LitImage, .sampled = Resource::GBuffer};
    constexpr Pass kLaterBatch{.name = "forward",
                               .target = Resource::LitImage,
                               .state = {.depthTest = DepthTest::Equal, .keepDepth = true, .blend = Blend::Add},
                               .sampled = Resource::GBuffer};
    for (const LightBatch& batch : lightBatches(static_cast<std::uint32_t>(scene.lightCount())))
        passes.run(batch.isFirst() ? kFirstBatch : kLaterBatch, [&] {
            if (batch.isFirst())
                targets.litFramebuffer.clearDepthStencil(1.0f, 0);
            scene.drawObjects([&](MaterialVariant maps) -> const gl::Program& {
                const gl::Program& program =
                    program_.variant(scene.lightingFeatures(), LightSource::StorageBuffer, maps);
                setLightBatch(program, batch);
                return program;
            });
        });
}

}  // namespace manylights
