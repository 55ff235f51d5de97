#include "render/SceneLights.h"

#include <algorithm>
#include <cmath>

#include "core/Error.h"
#include "render/Bindings.h"
#include "scene/Animation.h"
#include "scene/Falloff.h"

namespace manylights {

namespace {
// Binding point shared with the shaders (lib/lights.glsl).
constexpr GLuint kLightsBinding = bindings::LIGHTS_BUFFER_BINDING;
// Point lights get cos(cutoff) = −2: every direction passes the spot test and S = 1.
constexpr float kPointLightCosCutoff = -2.0f;
}  // namespace

static_assert(kLightsPerWindow * sizeof(GpuLight) == kLightWindowBytes);

GpuLight packLight(const Light& light, float attenuationThreshold)
{
    GpuLight packed{};
    packed.positionRadius = glm::vec4(light.position, lightRadius(light, attenuationThreshold));
    const bool spot = light.type == LightType::Spot;
    packed.intensityExponent = glm::vec4(light.intensity, spot ? light.exponent : 0.0f);
    if (light.falloff == Falloff::Classic)
        packed.attenuation =
            glm::vec4(light.attenuation.constant, light.attenuation.linear, light.attenuation.quadratic, 0.0f);
    else
        packed.attenuation = glm::vec4(light.range, 0.0f, 0.0f, 1.0f);
    packed.spotAxisCosCutoff =
        spot ? glm::vec4(glm::normalize(light.direction), std::cos(glm::radians(light.cutoffDegrees)))
             : glm::vec4(0.0f, 0.0f, 0.0f, kPointLightCosCutoff);
    return packed;
}

SceneLights::SceneLights(const std::vector<Light>& lights, float attenuationThreshold, const DriverChoices& driver)
    : rest_(lights),
      posed_(lights),
      attenuationThreshold_(attenuationThreshold),
      texelsBeforeWindows_(driver.lightTexelsBeforeWindows)
{
    packed_.reserve(lights.size());
    for (const Light& light : lights)
        packed_.push_back(packLight(light, attenuationThreshold_));
    // Dynamic storage: pose() rewrites it every frame of an animation.
    // Whole windows (bindWindow), so that every window bound is backed by the buffer.
    const std::size_t windows = std::max<std::size_t>(1, (packed_.size() + kLightsPerWindow - 1) / kLightsPerWindow);
    buffer_ = gl::Buffer("lights", windows * kLightWindowBytes, nullptr, GL_DYNAMIC_STORAGE_BIT);
    setTexels(true);
    pose(0.0);
}

void SceneLights::pose(double t)
{
    for (std::size_t i = 0; i < rest_.size(); ++i)
        posed_[i].position = animatedPosition(rest_[i].position, rest_[i].animation, t);
    for (std::size_t i = 0; i < posed_.size(); ++i)
        packed_[i] = packLight(posed_[i], attenuationThreshold_);
    if (!packed_.empty())
        buffer_.update(0, packed_.size() * sizeof(GpuLight), packed_.data());
    ++version_;
}

void SceneLights::bind() const
{
    buffer_.bindBase(GL_SHADER_STORAGE_BUFFER, kLightsBinding);
    if (texels_)
        texels_.bindUnit(kLightTexelsUnit);
}

void SceneLights::bindWindow(const LightBatch& batch) const
{
    ML_ASSERT(batch.first % kLightsPerWindow == 0);
    buffer_.bindRange(GL_UNIFORM_BUFFER, kLightWindowBinding, batch.first * sizeof(GpuLight), kLightWindowBytes);
}

void SceneLights::setTexels(bool wanted)
{
    if (wanted && lightTexelsSupported(packed_.size())) {
        if (!texels_)
            texels_ = gl::BufferTexture("light texels", GL_RGBA32F, buffer_);
    } else {
        texels_ = gl::BufferTexture();
    }
}

}  // namespace manylights
