#include "render/scene/SceneLights.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <string>

#include "core/Error.h"
#include "render/programs/Bindings.h"
#include "render/programs/Locations.h"
#include "render/programs/WorkgroupRows.h"
#include "scene/Animation.h"
#include "scene/Falloff.h"
#include "scene/SpatialOrder.h"

namespace manylights {

namespace {
// Binding point shared with the shaders (lib/lights.glsl).
constexpr GLuint kLightsBinding = bindings::LIGHTS_BUFFER_BINDING;
// Point lights get cos(cutoff) = −2: every direction passes the spot test and S = 1.
constexpr float kPointLightCosCutoff = -2.0f;
// shaders/pose_lights.comp's kinds of motion (POSE_ORBIT, POSE_DRIFT) and workgroup size.
constexpr std::uint32_t kOrbitMotion = 0;
constexpr std::uint32_t kDriftMotion = 1;
constexpr GLuint kPoseGroupSize = 64;
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

GpuLightMotion packMotion(const Light& light, std::uint32_t index)
{
    ML_ASSERT(light.animation);
    GpuLightMotion packed{};
    packed.restPosition = glm::vec4(light.position, std::bit_cast<float>(index));
    if (const auto* orbit = std::get_if<OrbitAnimation>(&*light.animation)) {
        packed.settings = glm::vec4(orbit->radius, orbit->degreesPerSecond, orbit->phaseDegrees, 0.0f);
        packed.periods = glm::vec4(0.0f, 0.0f, 0.0f, std::bit_cast<float>(kOrbitMotion));
    } else {
        const DriftAnimation& drift = std::get<DriftAnimation>(*light.animation);
        packed.settings = glm::vec4(drift.amplitude, drift.phaseDegrees);
        packed.periods = glm::vec4(drift.period, std::bit_cast<float>(kDriftMotion));
    }
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

}  // namespace

SceneLights::SceneLights(const std::vector<Light>& lights, float attenuationThreshold, const DriverChoices& driver)
    : rest_(inSpatialOrder(lights)),
      attenuationThreshold_(attenuationThreshold),
      texelsBeforeWindows_(driver.lightTexelsBeforeWindows)
{
    // Packed at time 0 on the CPU, uploaded with the lights at rest; the GPU poses the moving
    // ones from then on.
    std::vector<GpuLightMotion> motions;
    packed_.reserve(rest_.size());
    for (std::size_t i = 0; i < rest_.size(); ++i) {
        packed_.push_back(packLight(rest_[i], attenuationThreshold_));
        if (rest_[i].animation) {
            animated_.push_back(i);
            motions.push_back(packMotion(rest_[i], static_cast<std::uint32_t>(i)));
            const glm::vec3 atZero = animatedPosition(rest_[i].position, rest_[i].animation, 0.0);
            packed_[i].positionRadius = glm::vec4(atZero, packed_[i].positionRadius.w);
        }
    }
    // Whole windows (bindWindow), so that every window bound is backed by the buffer. Written
    // once from here; pose_lights.comp writes the moving lights' positions.
    const std::size_t windows = std::max<std::size_t>(1, (packed_.size() + kLightsPerWindow - 1) / kLightsPerWindow);
    buffer_ = gl::Buffer("lights", windows * kLightWindowBytes, nullptr, GL_DYNAMIC_STORAGE_BIT);
    if (!packed_.empty())
        buffer_.update(0, packed_.size() * sizeof(GpuLight), packed_.data());
    if (!motions.empty()) {
        motions_ = gl::Buffer::fromSpan<GpuLightMotion>("light motions", motions, 0);
        poseProgram_ = gl::Program(
            "pose lights", {{GL_COMPUTE_SHADER, "pose_lights.comp"}},
            {{"POSE_ORBIT", std::to_string(kOrbitMotion) + "u"}, {"POSE_DRIFT", std::to_string(kDriftMotion) + "u"}});
    }
    setTexels(true);
}

void SceneLights::pose(double t)
{
    // Lights at rest were packed and uploaded once: a frame pays for the lights that move.
    if (animated_.empty() || posedAt_ == t)
        return;
    posedAt_ = t;
    ++version_;
}

void SceneLights::applyPose()
{
    if (!posePending())
        return;
    const auto count = static_cast<GLuint>(animated_.size());
    buffer_.bindBase(GL_SHADER_STORAGE_BUFFER, kLightsBinding);
    motions_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::LIGHT_MOTIONS_BUFFER_BINDING);
    poseProgram_.set(locations::POSE_TIME_LOCATION, posedAt_);
    poseProgram_.set(locations::POSE_MOTION_COUNT_LOCATION, count);
    poseProgram_.use();
    dispatchComputeInRows((count + kPoseGroupSize - 1) / kPoseGroupSize);
    // Every later pass reads the lights in one of these ways: as storage, as texels, as a
    // uniform window, or back on the CPU (tests).
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_UNIFORM_BARRIER_BIT |
                    GL_BUFFER_UPDATE_BARRIER_BIT);
    gpuPosedAt_ = posedAt_;
}

void SceneLights::poseOnCpu() const
{
    if (cpuPosedAt_ == posedAt_)
        return;
    // A motion moves the light and nothing else: its radius and the rest stay as packed.
    for (std::size_t i : animated_)
        packed_[i].positionRadius =
            glm::vec4(animatedPosition(rest_[i].position, rest_[i].animation, posedAt_), packed_[i].positionRadius.w);
    cpuPosedAt_ = posedAt_;
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
