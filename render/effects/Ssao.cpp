#include "render/effects/Ssao.h"
#include "render/programs/Bindings.h"

#include <cmath>
#include <cstdint>

#include <glm/gtc/constants.hpp>

#include "render/frame/FramePasses.h"
#include "render/frame/TechniqueOptions.h"
#include "render/programs/Locations.h"
#include "render/scene/GpuScene.h"

namespace manylights {

namespace {

// Shared with shaders/ssao.comp and shaders/ssao_blur.comp.
constexpr GLuint kSamplesBinding = bindings::SSAO_SAMPLES_BUFFER_BINDING;
constexpr GLuint kOcclusionImageUnit = bindings::OCCLUSION_IMAGE_UNIT;
constexpr int kSsaoGroupSize = 8;
// Depth bias of the occlusion test, as a fraction of the radius: curved surfaces bend
// away from their own tangent plane, and the occluder's plane is a pixel's, not the sample's.
constexpr float kBiasFraction = 0.02f;
// The smallest elevation of a kernel point above the tangent plane: points grazing the plane
// would be decided by float rounding on flat surfaces.
constexpr float kMinElevationDegrees = 10.0f;
constexpr std::uint32_t kSeed = 0x55A0u;

// Numerical Recipes' 32-bit linear congruential generator: tiny and the same everywhere.
class Lcg {
public:
    explicit Lcg(std::uint32_t seed) : state_(seed) {}
    float next()  // uniform in [0, 1)
    {
        state_ = state_ * 1664525u + 1013904223u;
        return static_cast<float>(state_ >> 8) / 16777216.0f;
    }

private:
    std::uint32_t state_;
};

}  // namespace

SsaoSamples makeSsaoSamples()
{
    Lcg random(kSeed);
    SsaoSamples samples{};
    const float minZ = std::sin(glm::radians(kMinElevationDegrees));
    for (int i = 0; i < kSsaoKernelSize; ++i) {
        const float z = minZ + (1.0f - minZ) * random.next();
        const float phi = glm::two_pi<float>() * random.next();
        const float across = std::sqrt(1.0f - z * z);
        const float t = static_cast<float>(i) / static_cast<float>(kSsaoKernelSize);
        const float length = (0.1f + 0.9f * t * t) * (0.5f + 0.5f * random.next());
        samples.kernel[i] = glm::vec4(glm::vec3(across * std::cos(phi), across * std::sin(phi), z) * length, 0.0f);
    }
    for (glm::vec4& rotation : samples.noise) {
        const float phi = glm::two_pi<float>() * random.next();
        rotation = glm::vec4(std::cos(phi), std::sin(phi), 0.0f, 0.0f);
    }
    return samples;
}

Ssao::Ssao(GBufferLayout layout)
    : occlusionProgram_("ssao", {{GL_COMPUTE_SHADER, "ssao.comp"}},
                        ShaderVariant{.technique = {.gbufferLayout = layout}}.toDefines({})),
      blurProgram_("ssao blur", {{GL_COMPUTE_SHADER, "ssao_blur.comp"}})
{
    const SsaoSamples samples = makeSsaoSamples();
    samples_ = gl::Buffer("ssao kernel and noise", sizeof(SsaoSamples), &samples, 0);
}

void Ssao::resize(int width, int height)
{
    raw_ = gl::Texture2D("ssao raw", GL_R32F, width, height);
    blurred_ = gl::Texture2D("ssao blurred", GL_R32F, width, height);
}

void Ssao::run(const AmbientOcclusion& settings, FramePasses& passes)
{
    FrameTargets& targets = passes.targets();
    if (raw_.width() != targets.width || raw_.height() != targets.height)
        resize(targets.width, targets.height);
    targets.gbuffer.fill(passes);
    const auto groupsX = static_cast<GLuint>((targets.width + kSsaoGroupSize - 1) / kSsaoGroupSize);
    const auto groupsY = static_cast<GLuint>((targets.height + kSsaoGroupSize - 1) / kSsaoGroupSize);
    // The occlusion counts as part of the G-buffer (Resource::GBuffer): the passes that sample
    // it after these write it wait for them.
    constexpr Pass kSsaoPass{
        .name = "ssao", .sampled = Resource::GBuffer, .images = Resource::GBuffer, .writes = Resource::GBuffer};
    passes.run(kSsaoPass, [&] {
        samples_.bindBase(GL_SHADER_STORAGE_BUFFER, kSamplesBinding);
        occlusionProgram_.set(locations::SSAO_PARAMS_LOCATION,
                              glm::vec4(settings.radius, settings.strength, kBiasFraction * settings.radius, 0.0f));
        raw_.bindImage(kOcclusionImageUnit, GL_WRITE_ONLY);
        occlusionProgram_.use();
        glDispatchCompute(groupsX, groupsY, 1);
    });
    passes.run(kSsaoPass, [&] {
        raw_.bindUnit(kRawOcclusionUnit);
        blurred_.bindImage(kOcclusionImageUnit, GL_WRITE_ONLY);
        blurProgram_.use();
        glDispatchCompute(groupsX, groupsY, 1);
    });
    blurred_.bindUnit(kAmbientOcclusionUnit);
}

}  // namespace manylights
