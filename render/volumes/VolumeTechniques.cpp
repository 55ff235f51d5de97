#include "render/volumes/VolumeTechniques.h"

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
    : Technique(options),
      drawer_(shaderDefines(options)),
      stencilOnly_("stencil volumes", {{GL_VERTEX_SHADER, "volume.vert"}})
{
}

void StencilTechnique::render(const GpuScene& scene, FrameTargets&, FramePasses& passes)
{
    shadeGlobalTermsAndUnboundedLights(passes, drawer_);
    const auto shadeLight = [&](VolumeShape shape, std::size_t index) {
        passes.run(kMarkInsideVolume, [&] { drawer_.drawVolumes(shape, index, 1, stencilOnly_); });
        passes.run(kShadeMarked, [&] { drawer_.drawVolumes(shape, index, 1); });
    };
    // A sphere around the eye has no front face on screen: the stencil pass would mark exactly
    // the pixels whose surface lies in front of its back face, which the back faces drawn with
    // the reversed depth test (volumes' pass) shade directly, without the stencil pass. Runs
    // of such spheres are drawn as one instanced draw, in light order, so every pixel adds its
    // lights in the same order as with a stencil pass per light: the same image bit for bit.
    const std::vector<std::uint32_t>& spheres = drawer_.groups().spheres;
    const glm::vec3 eye(scene.frameUniforms().eye);
    const auto aroundEye = [&](std::size_t i) { return eyeInsideSphereVolume(scene.packedLights()[spheres[i]], eye); };
    for (std::size_t i = 0; i < spheres.size();) {
        std::size_t end = i;
        while (end < spheres.size() && aroundEye(end))
            ++end;
        if (end == i) {
            shadeLight(VolumeShape::Sphere, i++);
            continue;
        }
        passes.run(kBackFaceVolumes, [&] { drawer_.drawVolumes(VolumeShape::Sphere, i, end - i); });
        i = end;
    }
    for (std::size_t i = 0; i < drawer_.groups().cones.size(); ++i)
        shadeLight(VolumeShape::Cone, i);
}

}  // namespace manylights
