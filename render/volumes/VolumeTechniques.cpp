#include "render/volumes/VolumeTechniques.h"

#include "gl/CallTally.h"
#include "render/frame/ScreenPasses.h"
#include "render/scene/GpuScene.h"
#include "render/volumes/LightVolumes.h"

namespace manylights {

void shadeGlobalTermsAndUnboundedLights(FramePasses& passes, VolumeDrawer& drawer)
{
    passes.targets().gbuffer.fill(passes);
    drawer.prepare(passes.scene());
    passes.run({.name = "global", .target = Resource::LitImage, .state = kCoveredPixels, .sampled = Resource::GBuffer},
               [&] { drawer.drawGlobalTerms(); });
    // No volume encloses an unbounded light: it is added over every covered pixel.
    passes.run(
        {.name = "global", .target = Resource::LitImage, .state = kAddToCoveredPixels, .sampled = Resource::GBuffer},
        [&] { drawer.drawVolumes(VolumeShape::FullScreen, 0, drawer.groups().fullScreen.size()); });
}

namespace {

// Both techniques shade back faces: they exist for every pixel the volume covers, whether the
// camera is outside the volume or inside it. Depth clamping keeps the back faces that lie
// beyond the far plane (instead of clipping them away with the light they carry). A back face
// at or behind the surface: the surface lies in front of the volume's far side, so it may be
// inside. Surfaces in front of the whole volume pass too and get exactly zero from the light;
// surfaces behind it are skipped.
constexpr Pass kBackFaceVolumes{.name = "lighting",
                                .target = Resource::LitImage,
                                .state = {.depthTest = DepthTest::GreaterOrEqual,
                                          .keepDepth = true,
                                          .blend = Blend::Add,
                                          .cull = Cull::FrontFaces,
                                          .clampDepth = true},
                                .sampled = Resource::GBuffer};

// Stencil pass: no colour, no culling, depth test against the scene; a back face behind the
// surface adds 1, a front face behind it subtracts 1 (Stencil::CountVolumeFaces). With the
// camera inside the volume there is no front face and the back face alone decides. The stencil
// starts at 0 everywhere: the geometry pass cleared it.
constexpr Pass kMarkInsideVolume{
    .name = "lighting",
    .target = Resource::LitImage,
    .state = {.keepDepth = true, .clampDepth = true, .maskColour = true, .stencil = Stencil::CountVolumeFaces}};

// Lighting pass: the volume again, where the mark is set, resetting it to 0 so that the pixel
// is shaded once and the next light starts clean. Both faces are drawn: at the volume's
// silhouette a pixel centre may fall on a front triangle and on no back triangle (the
// rasteriser gives a shared edge to one side only), and a mark left there would corrupt the
// next light's count. Surfaces marked in front of or beside the volume are shaded too and get
// exactly zero from the light.
constexpr Pass kShadeMarked{.name = "lighting",
                            .target = Resource::LitImage,
                            .state = {.depthTest = DepthTest::Off,
                                      .keepDepth = true,
                                      .blend = Blend::Add,
                                      .clampDepth = true,
                                      .stencil = Stencil::PassMarkedAndClear},
                            .sampled = Resource::GBuffer};

}  // namespace

void VolumesTechnique::render(const GpuScene&, FrameTargets&, FramePasses& passes)
{
    shadeGlobalTermsAndUnboundedLights(passes, drawer_);
    passes.run(kBackFaceVolumes, [&] {
        drawer_.drawVolumes(VolumeShape::Sphere, 0, drawer_.groups().spheres.size());
        drawer_.drawVolumes(VolumeShape::Cone, 0, drawer_.groups().cones.size());
    });
}

StencilTechnique::StencilTechnique(const TechniqueOptions& options)
    : Technique(options), drawer_(options.shaders), stencilOnly_("stencil volumes", {{GL_VERTEX_SHADER, "volume.vert"}})
{
}

std::vector<TechniqueCounter> StencilTechnique::counters() const
{
    const double perLight =
        volumeLights_ > 0 ? static_cast<double>(glCalls_) / static_cast<double>(volumeLights_) : 0.0;
    return {{"gl_calls", static_cast<double>(glCalls_)},
            {"gl_calls_per_light", perLight},
            {"stencil_batches", static_cast<double>(batchCount_)}};
}

void StencilTechnique::render(const GpuScene& scene, FrameTargets& targets, FramePasses& passes)
{
    shadeGlobalTermsAndUnboundedLights(passes, drawer_);
    const std::uint64_t callsBefore = gl::callTally();
    const FrameUniforms& frame = scene.frameUniforms();
    const StencilBatchView view{.view = frame.view,
                                .eye = glm::vec3(frame.eye),
                                .tanHalfFovX = frame.projection.x,
                                .tanHalfFovY = frame.projection.y,
                                .width = targets.width,
                                .height = targets.height};
    // The batches follow the camera and the lights: a frame that moved neither keeps them.
    const BatchesMadeFor madeFor{&scene, scene.lightsVersion(), view};
    if (madeFor != batchesMadeFor_) {
        batcher_.group(view, scene.packedLights(), drawer_.groups());
        gl::uploadGrowing<std::uint32_t>(batchOrder_, "stencil batch order", batcher_.batches().order);
        batchesMadeFor_ = madeFor;
    }
    const StencilBatches& batches = batcher_.batches();

    // A sphere around the eye has no front face on screen: the stencil pass would mark exactly
    // the pixels whose surface lies in front of its back face, which the back faces drawn with
    // the reversed depth test (volumes' pass) shade directly, without the stencil pass. They
    // need no stencil, so they may overlap: all of them are one instanced draw.
    if (batches.aroundEye > 0)
        passes.run(kBackFaceVolumes, [&] {
            drawer_.drawListed(batchOrder_, VolumeShape::Sphere, 0, batches.aroundEye, drawer_.lightingProgram());
        });
    // A batch's volumes cover disjoint pixels (render/volumes/StencilBatches.h): its stencil pass
    // marks each pixel for one volume at most, and its lighting pass clears every mark.
    for (const StencilBatch& batch : batches.batches) {
        const auto drawBatch = [&](const gl::Program& program) {
            drawer_.drawListed(batchOrder_, VolumeShape::Sphere, batch.first, batch.spheres, program);
            drawer_.drawListed(batchOrder_, VolumeShape::Cone, batch.first + batch.spheres, batch.cones, program);
        };
        passes.run(kMarkInsideVolume, [&] { drawBatch(stencilOnly_); });
        passes.run(kShadeMarked, [&] { drawBatch(drawer_.lightingProgram()); });
    }
    glCalls_ = gl::callTally() - callsBefore;
    volumeLights_ = drawer_.groups().spheres.size() + drawer_.groups().cones.size();
    batchCount_ = batches.batches.size();
}

}  // namespace manylights
