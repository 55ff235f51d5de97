#include "render/environment/EnvironmentLight.h"
#include "render/programs/Bindings.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "gl/Driver.h"
#include "render/environment/EnvironmentFiles.h"

namespace manylights {

namespace {

constexpr int kPrefilterGroupSize = 8;  // local_size of shaders/environment_prefilter.comp

}  // namespace

EnvironmentLight::EnvironmentLight()
    : radiance_("environment radiance (none)", kRadianceFormat, 1, 1, 1),
      uniforms_("environment", sizeof(EnvironmentUniforms), nullptr)
{
    const float black[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    radiance_.writeLevel(0, GL_RGBA, GL_FLOAT, black);
    upload();
}

EnvironmentLight::EnvironmentLight(const Environment& environment)
    : present_(true), look_(environment.look), uniforms_("environment", sizeof(EnvironmentUniforms), nullptr)
{
    const auto start = std::chrono::steady_clock::now();
    const EnvironmentImage map = loadEnvironmentImage(environment.map, gl::queryInteger(GL_MAX_TEXTURE_SIZE));
    sh_ = irradianceSh(map);
    radiance_ = gl::MipmappedTexture2D("environment radiance", kRadianceFormat, kRadianceWidth, kRadianceWidth / 2,
                                       kRadianceLevels);
    prefilterProgram_ = prefilterProgram(kRadianceFormat);
    prefilter(map, radiance_, prefilterProgram_);
    upload();
    glFinish();
    loadMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

gl::Program EnvironmentLight::prefilterProgram(GLenum format)
{
    return gl::Program("environment prefilter", {{GL_COMPUTE_SHADER, "environment_prefilter.comp"}},
                       {{"MAX_PREFILTER_SAMPLES", std::to_string(kMaxPrefilterSamples)},
                        {"ENVIRONMENT_FORMAT", format == GL_RGBA16F ? "rgba16f" : "rgba32f"}});
}

void EnvironmentLight::prefilter(const EnvironmentImage& map, const gl::MipmappedTexture2D& radiance,
                                 const gl::Program& program)
{
    // The map with its mipmaps (the filtered importance sampling reads them), as floats: a
    // map's radiance spans far more than half floats' steps near 1 keep apart.
    gl::MipmappedTexture2D source("environment map", GL_RGBA32F, map.width, map.height,
                                  gl::fullMipmapLevels(map.width, map.height));
    // The map's rows run top to bottom, and so does v: its first row is the texture's first.
    source.writeLevel(0, GL_RGB, GL_FLOAT, map.radiance.data());
    source.generateMipmaps();
    source.setWrap(GL_REPEAT, GL_CLAMP_TO_EDGE);
    radiance.setWrap(GL_REPEAT, GL_CLAMP_TO_EDGE);

    program.use();
    source.bindUnit(bindings::ENVIRONMENT_SOURCE_UNIT);
    for (int level = 0; level < radiance.levels(); ++level) {
        program.set(0, static_cast<float>(level) / static_cast<float>(std::max(radiance.levels() - 1, 1)));
        program.set(1, static_cast<unsigned>(prefilterSamples(level)));
        radiance.bindImage(bindings::ENVIRONMENT_LEVEL_IMAGE_UNIT, level, GL_WRITE_ONLY);
        glDispatchCompute(
            static_cast<GLuint>((radiance.levelWidth(level) + kPrefilterGroupSize - 1) / kPrefilterGroupSize),
            static_cast<GLuint>((radiance.levelHeight(level) + kPrefilterGroupSize - 1) / kPrefilterGroupSize), 1);
    }
    // The levels are sampled (the lighting), read back (tests) or fetched from here on.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

void EnvironmentLight::bind() const
{
    uniforms_.bindBase(GL_UNIFORM_BUFFER, bindings::ENVIRONMENT_BLOCK_BINDING);
    radiance_.bindUnit(bindings::ENVIRONMENT_RADIANCE_UNIT);
}

void EnvironmentLight::setLook(const EnvironmentLook& look)
{
    if (!present_ || look == look_)
        return;
    look_ = look;
    upload();
}

void EnvironmentLight::upload()
{
    EnvironmentUniforms uniforms{};
    const float intensity = present_ ? look_.intensity : 0.0f;
    for (std::size_t k = 0; k < sh_.size(); ++k)
        uniforms.irradianceSh[k] = glm::vec4(sh_[k] * intensity, 0.0f);
    const double angle = static_cast<double>(look_.rotationDegrees) * std::numbers::pi / 180.0;
    uniforms.lookup = glm::vec4(static_cast<float>(std::cos(angle)), static_cast<float>(std::sin(angle)), intensity,
                                static_cast<float>(radiance_.levels() - 1));
    uniforms_.update(0, sizeof uniforms, &uniforms);
}

}  // namespace manylights
