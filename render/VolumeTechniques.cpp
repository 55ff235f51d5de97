#include "render/VolumeTechniques.h"

#include "render/GpuScene.h"
#include "render/PassProfiler.h"
#include "render/ScreenPasses.h"

namespace manylights {

void shadeGlobalTermsAndUnboundedLights(const GpuScene& scene, FrameTargets& targets, PassProfiler& profiler,
                                        VolumeDrawer& drawer)
{
    targets.gbuffer.fill(scene, profiler);
    drawer.prepare(scene);
    auto pass = profiler.pass("global");
    targets.litFramebuffer.bind();
    scene.bind();
    targets.gbuffer.bindForReading();
    glDisable(GL_BLEND);
    drawer.drawGlobalTerms();
    // No volume encloses an unbounded light: it is added over every covered pixel.
    beginAddingToCoveredPixels();
    drawer.drawVolumes(VolumeShape::FullScreen, 0, drawer.groups().fullScreen.size());
}

namespace {

// Both techniques shade back faces: they exist for every pixel the volume covers, whether
// the camera is outside the volume or inside it. Depth clamping keeps the back faces that
// lie beyond the far plane (instead of clipping them away with the light they carry).
void beginBackFaceVolumes()
{
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    glEnable(GL_DEPTH_CLAMP);
}

void restoreDefaultState()
{
    glDisable(GL_CULL_FACE);
    glDisable(GL_DEPTH_CLAMP);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
}

}  // namespace

void VolumesTechnique::render(const GpuScene& scene, FrameTargets& targets, PassProfiler& profiler)
{
    shadeGlobalTermsAndUnboundedLights(scene, targets, profiler, drawer_);
    auto pass = profiler.pass("lighting");
    beginBackFaceVolumes();
    // A back face at or behind the surface: the surface lies in front of the volume's far
    // side, so it may be inside. Surfaces in front of the whole volume pass too and get
    // exactly zero from the light; surfaces behind it are skipped.
    glDepthFunc(GL_GEQUAL);
    drawer_.drawVolumes(VolumeShape::Sphere, 0, drawer_.groups().spheres.size());
    drawer_.drawVolumes(VolumeShape::Cone, 0, drawer_.groups().cones.size());
    restoreDefaultState();
}

StencilTechnique::StencilTechnique(const TechniqueOptions& options)
    : Technique(options),
      drawer_(shaderDefines(options)),
      stencilOnly_("stencil volumes", {{GL_VERTEX_SHADER, "volume.vert"}})
{
}

void StencilTechnique::render(const GpuScene& scene, FrameTargets& targets, PassProfiler& profiler)
{
    shadeGlobalTermsAndUnboundedLights(scene, targets, profiler, drawer_);
    // The stencil starts at 0 everywhere: the geometry pass cleared it.
    auto pass = profiler.pass("lighting");
    glEnable(GL_STENCIL_TEST);
    glEnable(GL_DEPTH_CLAMP);
    const auto shadeLight = [&](VolumeShape shape, std::size_t index) {
        // Stencil pass: no colour, no culling, depth test against the scene; a back face
        // behind the surface adds 1, a front face behind it subtracts 1. Along a pixel's ray
        // through a convex volume the mark ends non-zero exactly when the surface lies
        // between the front and the back face: inside. With the camera inside the volume
        // there is no front face and the back face alone decides.
        glDisable(GL_CULL_FACE);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glStencilFunc(GL_ALWAYS, 0, 0xFF);
        glStencilOpSeparate(GL_BACK, GL_KEEP, GL_INCR_WRAP, GL_KEEP);
        glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_DECR_WRAP, GL_KEEP);
        drawer_.drawVolumes(shape, index, 1, stencilOnly_);
        // Lighting pass: the volume again, where the mark is set, resetting it to 0 so that
        // the pixel is shaded once and the next light starts clean. Both faces are drawn:
        // at the volume's silhouette a pixel centre may fall on a front triangle and on no
        // back triangle (the rasteriser gives a shared edge to one side only), and a mark
        // left there would corrupt the next light's count. Surfaces marked in front of or
        // beside the volume are shaded too and get exactly zero from the light.
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glDisable(GL_DEPTH_TEST);
        glStencilFunc(GL_NOTEQUAL, 0, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_ZERO);
        drawer_.drawVolumes(shape, index, 1);
    };
    for (std::size_t i = 0; i < drawer_.groups().spheres.size(); ++i)
        shadeLight(VolumeShape::Sphere, i);
    for (std::size_t i = 0; i < drawer_.groups().cones.size(); ++i)
        shadeLight(VolumeShape::Cone, i);
    restoreDefaultState();
}

}  // namespace manylights
