// forward: the reference. Every fragment of every object loops over every light.
#include "render/techniques/ForwardTechnique.h"

#include "render/frame/FramePasses.h"
#include "render/programs/LightBatches.h"
#include "render/scene/GpuScene.h"

namespace manylights {

ForwardTechnique::ForwardTechnique(const TechniqueOptions& options)
    : Technique(options),
      program_("forward", {{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "forward.frag"}}, options.shaders)
{
}

void ForwardTechnique::render(const GpuScene& scene, FrameTargets& targets, FramePasses& passes)
{
    // A depth pre-pass first, then one draw of the objects per light batch with the depth test
    // GL_EQUAL: the lighting runs for the visible fragments only, not for those a nearer
    // surface drawn later hides (on the default scene 2.4 fragments per covered pixel).
    // mesh.vert's invariant position gives both programs the same depths. Fragments that tie
    // at a pixel's depth would all pass GL_EQUAL; the stencil lets the first drawn through,
    // once per batch (Stencil::OncePerPixel), which is the one a single GL_LESS pass keeps.
    // Forward reads no G-buffer, but its ambient term reads SSAO's occlusion, which counts as
    // part of it (Resource::GBuffer): the passes wait for SSAO's image stores.
    constexpr Pass kDepthPrepass{.name = "depth", .target = Resource::LitImage, .state = {.maskColour = true}};
    passes.run(kDepthPrepass, [&] {
        targets.litFramebuffer.clearDepthStencil(1.0f, 0);
        scene.drawObjects([&](MaterialVariant maps) -> const gl::Program& {
            // It evaluates no light: the variants differ only in the material's maps.
            return program_.variant(ShaderVariant{.material = maps, .depthPrepass = true});
        });
    });
    // Every fragment walks the same lights in order: as deferred's, a batch's lights come from
    // a uniform window on a GPU and as texels on a software rasteriser
    // (GpuScene::readsLightWindows). The depth pre-pass reads no light at all.
    const LightSource source = scene.walkedLightSource();
    std::uint8_t batchNumber = 0;  // the stencil wraps as the reference does
    for (const LightBatch& batch :
         lightBatches(static_cast<std::uint32_t>(scene.lightCount()), lightsPerBatch(source))) {
        const Pass lighting{.name = "forward",
                            .target = Resource::LitImage,
                            .state = {.depthTest = DepthTest::Equal,
                                      .keepDepth = true,
                                      .blend = batch.isFirst() ? Blend::Replace : Blend::Add,
                                      .stencil = Stencil::OncePerPixel,
                                      .stencilReference = batchNumber++},
                            .sampled = Resource::GBuffer};
        passes.run(lighting, [&] {
            scene.bindLightSource(source, batch);
            scene.drawObjects([&](MaterialVariant maps) -> const gl::Program& {
                const gl::Program& program = program_.variant(scene.lightingFeatures(), source, maps);
                setLightBatch(program, batch);
                return program;
            });
        });
    }
}

}  // namespace manylights
