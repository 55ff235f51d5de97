#include "render/environment/EnvironmentLight.h"
#include "render/programs/Bindings.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <span>
#include <string>
#include <vector>

#include "gl/Driver.h"
#include "render/environment/EnvironmentFiles.h"
#include "render/environment/PrefilterSource.h"

namespace manylights {

namespace {

constexpr int kPrefilterGroupSize = 8;  // local_size of shaders/environment_prefilter.comp
// What the prefiltering reads (render/environment/PrefilterSource.h): the map box-filtered to
// at most kPrefilterSourceWidth, whose texels (0.35°) are a small part of the narrowest lobe
// (roughness 0.2: half its light within 5.9° of its axis), split at its brightest texels, of
// which at most kMaxBrightTexels are summed exactly at every texel of every level.
constexpr int kPrefilterSourceWidth = 1024;
constexpr int kMaxBrightTexels = 512;
// Filtered importance samples per texel of the remainder (shaders/environment_prefilter.comp):
// 64 for the first level, 128 for the second, 256 for the rest. Filtered importance sampling
// reads a mipmap as wide as each sample's share of the lobe, so the fewer the samples the
// blurrier the estimate: with these every level is within 2% of the integral on a smooth map
// (tests/gl/EnvironmentLightTest.cpp; 64 for every level left the roughest 8% off, 128 4%).
// The first level (256x128 texels, a narrow lobe) needs few, and 256 there would take three
// times as long at load (docs/performance.md). The same on every driver: a GPU could take
// more for nearly nothing, but the image would then depend on the driver, and every
// technique under either driver profile is compared with one reference.
constexpr int kMaxPrefilterSamples = 256;
constexpr int prefilterSamples(int level) { return level == 0 ? 64 : level == 1 ? 128 : 256; }

}  // namespace

EnvironmentLight::EnvironmentLight()
    : map_("environment map (none)", kRadianceFormat, 1, 1, 1),
      radiance_("environment radiance (none)", kRadianceFormat, 1, 1, 1, 1),
      uniforms_("environment", sizeof(EnvironmentUniforms), nullptr)
{
    const float black[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    map_.writeLevel(0, GL_RGBA, GL_FLOAT, black);
    radiance_.writeLayer(0, 0, GL_RGBA, GL_FLOAT, black);
    upload();
}

EnvironmentLight::EnvironmentLight(const Environment& environment, int maxMapWidth)
    : present_(true), look_(environment.look), uniforms_("environment", sizeof(EnvironmentUniforms), nullptr)
{
    const auto start = std::chrono::steady_clock::now();
    radiance_ = gl::LayeredTexture("environment radiance", kRadianceFormat, kRadianceWidth, kRadianceWidth / 2,
                                   kRadianceMips, kRadianceLevels);
    prefilterProgram_ = prefilterProgram(kRadianceFormat);
    {
        // The map's CPU copy lives only in this scope: uploaded as level 0, summed into the
        // harmonics and the prefiltering's smaller source, then freed, so that a large map's
        // peak memory is about its decoded pixels and the texture of level 0 (docs/performance.md).
        EnvironmentImage map = loadEnvironmentImage(environment.map, gl::queryInteger(GL_MAX_TEXTURE_SIZE));
        if (map.width > maxMapWidth) {
            const std::string size = std::to_string(map.width) + "x" + std::to_string(map.height);
            map = downsampledEnvironment(map, maxMapWidth);
            warnings_.push_back(environment.map + ": environment map is " + size + ", shown and reflected at " +
                                std::to_string(map.width) + "x" + std::to_string(map.height) +
                                ", the largest level 0 kept");
        }
        sh_ = irradianceSh(map);
        map_ = gl::MipmappedTexture2D("environment map", kRadianceFormat, map.width, map.height, 1);
        // The map's rows run top to bottom, and so does v: its first row is the texture's first.
        map_.writeLevel(0, GL_RGB, GL_FLOAT, map.radiance.data());
        map_.setWrap(GL_REPEAT, GL_CLAMP_TO_EDGE);
        prefilter(map, radiance_, prefilterProgram_);
    }
    upload();
    glFinish();
    loadMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

gl::Program EnvironmentLight::prefilterProgram(GLenum format)
{
    return gl::Program("environment prefilter", {{GL_COMPUTE_SHADER, "environment_prefilter.comp"}},
                       {{"MAX_PREFILTER_SAMPLES", std::to_string(kMaxPrefilterSamples)},
                        {"MAX_BRIGHT_TEXELS", std::to_string(kMaxBrightTexels)},
                        {"ENVIRONMENT_FORMAT", format == GL_RGBA16F ? "rgba16f" : "rgba32f"}});
}

void EnvironmentLight::prefilter(const EnvironmentImage& map, const gl::LayeredTexture& radiance,
                                 const gl::Program& program)
{
    const PrefilterSource split = splitForPrefiltering(map, kPrefilterSourceWidth, kMaxBrightTexels);
    // The remainder with its mipmaps (the filtered importance sampling reads them), as floats: a
    // map's radiance spans far more than half floats' steps near 1 keep apart.
    const EnvironmentImage& remainder = split.remainder;
    gl::MipmappedTexture2D source("environment prefilter source", GL_RGBA32F, remainder.width, remainder.height,
                                  gl::fullMipmapLevels(remainder.width, remainder.height));
    source.writeLevel(0, GL_RGB, GL_FLOAT, remainder.radiance.data());
    source.generateMipmaps();
    source.setWrap(GL_REPEAT, GL_CLAMP_TO_EDGE);
    radiance.setWrap(GL_REPEAT, GL_CLAMP_TO_EDGE);
    // At least one element: a storage block may not be bound to an empty buffer.
    std::vector<BrightTexel> bright = split.bright;
    if (bright.empty())
        bright.push_back({});
    const gl::Buffer brightTexels =
        gl::Buffer::fromSpan("environment bright texels", std::span<const BrightTexel>(bright));

    program.use();
    source.bindUnit(bindings::ENVIRONMENT_SOURCE_UNIT);
    brightTexels.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::ENVIRONMENT_BRIGHT_TEXELS_BUFFER_BINDING);
    program.set(2, static_cast<unsigned>(split.bright.size()));
    for (int layer = 0; layer < radiance.layers(); ++layer) {
        const double roughness = (layer + 1.0) / radiance.layers();
        const int mip = std::min(radianceMip(layer), radiance.levels() - 1);
        program.set(0, static_cast<float>(roughness));
        program.set(1, static_cast<unsigned>(prefilterSamples(layer)));
        program.set(3, static_cast<float>(1.0 / ggxLobeIntegral(roughness)));
        radiance.bindImage(bindings::ENVIRONMENT_LEVEL_IMAGE_UNIT, mip, layer, GL_WRITE_ONLY);
        glDispatchCompute(
            static_cast<GLuint>((radiance.levelWidth(mip) + kPrefilterGroupSize - 1) / kPrefilterGroupSize),
            static_cast<GLuint>((radiance.levelHeight(mip) + kPrefilterGroupSize - 1) / kPrefilterGroupSize), 1);
    }
    // The levels are sampled (the lighting), read back (tests) or fetched from here on.
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

void EnvironmentLight::bind() const
{
    uniforms_.bindBase(GL_UNIFORM_BUFFER, bindings::ENVIRONMENT_BLOCK_BINDING);
    map_.bindUnit(bindings::ENVIRONMENT_MAP_UNIT);
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
                                static_cast<float>(kRadianceLevels));
    uniforms_.update(0, sizeof uniforms, &uniforms);
}

}  // namespace manylights
