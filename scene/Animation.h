// Animation as a pure function of time (docs/scene-format.md: a scene rendered at a given --time is a
// function of that time alone). An object or light carries an optional description of its
// motion; objectTransformAt / lightAt evaluate it at any time t in seconds, with no state, so
// frame 100 of a recording is the same image whether or not frames 0..99 were rendered.
// No GL here: the render layer calls these per frame, tests sample them.
#pragma once

#include <optional>
#include <variant>

#include <glm/glm.hpp>

namespace manylights {

// Rotation about a world-space axis through `pivot` (default: the object's origin, the
// translation of its rest transform). About the vertical axis an object resting on the floor
// keeps resting on it.
struct SpinAnimation {
    glm::vec3 axis{0.0f, 1.0f, 0.0f};
    std::optional<glm::vec3> pivot;
    float degreesPerSecond = 45.0f;
    float phaseDegrees = 0.0f;
};

// A horizontal shear proportional to the height above `base`: x' = x + k(t)·(y − base)·d, with
// k(t) = amplitude · sin(2π·frequency·t + phase). Points at the base do not move and heights
// do not change, so an object standing on the floor sways from side to side, glued to it.
struct SwayAnimation {
    glm::vec3 direction{1.0f, 0.0f, 0.0f};  // horizontal; normalised when evaluated
    float amplitude = 0.2f;                 // shear factor at the peak (0.2: 1 unit up moves 0.2)
    float frequency = 0.5f;                 // Hz
    float phaseDegrees = 0.0f;
    float base = 0.0f;  // the height that stays fixed (the floor)
};

// Hops of `height` every `period` seconds: the height above the rest pose is the parabola
// 4·h·s·(1 − s), s the fraction of the period (a body under constant gravity). With `squash`
// > 0 the object gets thinner in X and Z in proportion to its speed (by the factor
// 1 − squash · |v| / vmax) and taller by the inverse of that factor, both about the bottom of
// its rest pose at `base`: it touches the floor at s = 0 and never goes below it.
struct BounceAnimation {
    float height = 1.0f;
    float period = 1.0f;  // seconds, > 0
    float phase = 0.0f;   // fraction of a period, [0, 1)
    float squash = 0.0f;  // [0, 1)
    float base = 0.0f;    // the floor the object rests on in its rest pose
};

// A circle in the horizontal plane around the light's position (its rest position is the
// centre): position = centre + radius·(cos θ, 0, sin θ), θ = phase + speed·t.
struct OrbitAnimation {
    float radius = 1.0f;
    float degreesPerSecond = 30.0f;
    float phaseDegrees = 0.0f;
};

// A Lissajous wander around the rest position: offset_i = amplitude_i · sin(2π·t / period_i + phase).
struct DriftAnimation {
    glm::vec3 amplitude{1.0f, 0.0f, 1.0f};
    glm::vec3 period{7.0f, 5.0f, 11.0f};  // seconds per axis, each > 0
    float phaseDegrees = 0.0f;
};

using ObjectAnimation = std::variant<SpinAnimation, SwayAnimation, BounceAnimation>;
using LightAnimation = std::variant<OrbitAnimation, DriftAnimation>;

// The object's transform at time t, given its rest transform.
glm::mat4 animatedTransform(const glm::mat4& rest, const std::optional<ObjectAnimation>& animation, double t);

// A light's position at time t, given its rest position.
glm::vec3 animatedPosition(const glm::vec3& rest, const std::optional<LightAnimation>& animation, double t);

// The same animation with its phase advanced by `degrees` (light sets spread their lights'
// phases so that they do not move in lockstep).
LightAnimation withExtraPhase(LightAnimation animation, float degrees);

}  // namespace manylights
