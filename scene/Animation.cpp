#include "scene/Animation.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace manylights {

namespace {

constexpr double kTwoPi = 6.283185307179586;

// Angles are reduced in double before they become floats: at t = 10⁴ s a float angle would
// already be off by a visible fraction of a degree.
float sinTurns(double turns)
{
    const double fraction = turns - std::floor(turns);
    return static_cast<float>(std::sin(kTwoPi * fraction));
}

float wrapDegrees(double degrees) { return static_cast<float>(std::fmod(degrees, 360.0)); }

glm::mat4 spin(const glm::mat4& rest, const SpinAnimation& a, double t)
{
    const glm::vec3 pivot = a.pivot.value_or(glm::vec3{rest[3]});
    const float angle = glm::radians(wrapDegrees(a.phaseDegrees + a.degreesPerSecond * t));
    glm::mat4 about = glm::translate(glm::mat4{1.0f}, pivot);
    about = glm::rotate(about, angle, glm::normalize(a.axis));
    about = glm::translate(about, -pivot);
    return about * rest;
}

glm::mat4 sway(const glm::mat4& rest, const SwayAnimation& a, double t)
{
    const float k = a.amplitude * sinTurns(a.frequency * t + a.phaseDegrees / 360.0);
    glm::vec3 direction{a.direction.x, 0.0f, a.direction.z};
    direction = glm::normalize(direction);
    // Column-major: column 1 (the y basis) gains k·d, and the translation compensates so that
    // y = base stays in place.
    glm::mat4 shear{1.0f};
    shear[1] += glm::vec4(k * direction, 0.0f);
    shear[3] -= glm::vec4(k * a.base * direction, 0.0f);
    return shear * rest;
}

glm::mat4 bounce(const glm::mat4& rest, const BounceAnimation& a, double t)
{
    const double cycles = t / a.period + a.phase;
    const auto s = static_cast<float>(cycles - std::floor(cycles));
    const float lift = 4.0f * a.height * s * (1.0f - s);
    // Speed as a fraction of the fastest (at take-off and landing): |1 − 2s|.
    const float speed = std::abs(1.0f - 2.0f * s);
    const float thin = 1.0f - a.squash * speed;
    const float tall = 1.0f / thin;
    const glm::vec3 foot{rest[3].x, a.base, rest[3].z};
    glm::mat4 motion = glm::translate(glm::mat4{1.0f}, foot + glm::vec3{0.0f, lift, 0.0f});
    motion = glm::scale(motion, glm::vec3{thin, tall, thin});
    motion = glm::translate(motion, -foot);
    return motion * rest;
}

}  // namespace

glm::mat4 animatedTransform(const glm::mat4& rest, const std::optional<ObjectAnimation>& animation, double t)
{
    if (!animation)
        return rest;
    if (const auto* a = std::get_if<SpinAnimation>(&*animation))
        return spin(rest, *a, t);
    if (const auto* a = std::get_if<SwayAnimation>(&*animation))
        return sway(rest, *a, t);
    return bounce(rest, std::get<BounceAnimation>(*animation), t);
}

glm::vec3 animatedPosition(const glm::vec3& rest, const std::optional<LightAnimation>& animation, double t)
{
    if (!animation)
        return rest;
    if (const auto* orbit = std::get_if<OrbitAnimation>(&*animation)) {
        const float angle = glm::radians(wrapDegrees(orbit->phaseDegrees + orbit->degreesPerSecond * t));
        return rest + orbit->radius * glm::vec3{std::cos(angle), 0.0f, std::sin(angle)};
    }
    const DriftAnimation& drift = std::get<DriftAnimation>(*animation);
    glm::vec3 offset;
    for (int i = 0; i < 3; ++i)
        offset[i] = drift.amplitude[i] * sinTurns(t / drift.period[i] + drift.phaseDegrees / 360.0);
    return rest + offset;
}

LightAnimation withExtraPhase(LightAnimation animation, float degrees)
{
    std::visit([&](auto& a) { a.phaseDegrees = wrapDegrees(static_cast<double>(a.phaseDegrees) + degrees); },
               animation);
    return animation;
}

}  // namespace manylights
