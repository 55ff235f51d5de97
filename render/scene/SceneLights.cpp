#include "render/scene/SceneLights.h"

#include <algorithm>
#include <cmath>

#include "core/Error.h"
#include "render/programs/Bindings.h"
#include "scene/Animation.h"
#include "scene/Falloff.h"
#include "scene/SpatialOrder.h"

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

namespace {

// The lights in the order of their rest positions along a Morton curve (scene/SpatialOrder.h).
std::vector<Light> inSpatialOrder(const std::vector<Light>& lights)
{
    std::vector<glm::vec3> positions;
    positions.reserve(lights.size());
    for (const Light& light : lights)
        positions.push_back(light.position);
    std::vector<Light> ordered;
    ordered.reserve(lights.size());
    for (std::size_t i : mortonOrder(positions))
        ordered.push_back(lights[i]);
    return ordered;
}

// Runs of animated lights closer than this are uploaded as one range: fewer calls for a few
// more bytes.
constexpr std::size_t kUploadRunGap = 64;

}  // namespace

SceneLights::SceneLights(const std::vector<Light>& lights, float attenuationThreshold, const DriverChoices& driver)
    : rest_(inSpatialOrder(lights)),
      posed_(rest_),
      attenuationThreshold_(attenuationThreshold),
      texelsBeforeWindows_(driver.lightTexelsBeforeWindows)
{
    packed_.reserve(rest_.size());
    for (std::size_t i = 0; i < rest_.size(); ++i) {
        packed_.push_back(packLight(rest_[i], attenuationThreshold_));
        if (rest_[i].animation)
            animated_.push_back(i);
    }
    // Whole windows (bindWindow), so that every window bound is backed by the buffer. Dynamic
    // storage: pose() rewrites the animated lights' part every frame of an animation.
    const std::size_t windows = std::max<std::size_t>(1, (packed_.size() + kLightsPerWindow - 1) / kLightsPerWindow);
    buffer_ = gl::Buffer("lights", windows * kLightWindowBytes, nullptr, GL_DYNAMIC_STORAGE_BIT);
    if (!packed_.empty())
        buffer_.update(0, packed_.size() * sizeof(GpuLight), packed_.data());
    setTexels(true);
    pose(0.0);
}

void SceneLights::pose(double t)
{
    // Lights at rest were packed and uploaded once: a frame pays for the lights that move.
    if (animated_.empty() || posedAt_ == t)
        return;
    for (std::size_t i : animated_) {
        posed_[i].position = animatedPosition(rest_[i].position, rest_[i].animation, t);
        packed_[i] = packLight(posed_[i], attenuationThreshold_);
    }
    for (std::size_t run = 0; run < animated_.size();) {
        std::size_t end = run + 1;
        while (end < animated_.size() && animated_[end] - animated_[end - 1] <= kUploadRunGap)
            ++end;
        const std::size_t first = animated_[run];
        const std::size_t count = animated_[end - 1] + 1 - first;
        buffer_.update(first * sizeof(GpuLight), count * sizeof(GpuLight), &packed_[first]);
        run = end;
    }
    posedAt_ = t;
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
