// The viewer's camera moves, as pure functions on scene::Camera (tested without a window):
// orbit about the look-at point, dolly towards it, fly (eye and look-at together), and look
// around from the eye; and the held keys' moves at their rates (docs/viewer.md "Controls").
#pragma once

#include <glm/glm.hpp>

#include "apps/view/Keymaps.h"
#include "scene/Scene.h"

namespace manylights {

// The camera's speeds while a key is held, per second of holding.
inline constexpr float kOrbitDegreesPerSecond = 60.0f;  // orbit and look
inline constexpr float kDollyPerSecond = 1.5f;          // distance factor per second
inline constexpr float kFlyFractionPerSecond = 0.4f;    // of the distance to the look-at point

// Turns the eye about the look-at point: yaw about the camera's up, pitch towards or away from
// it (stopping 5° short of the poles, where the view basis would degenerate).
void orbitCamera(Camera& camera, float yawDegrees, float pitchDegrees);

// Moves the eye towards the look-at point (factor < 1) or away from it (> 1); never closer
// than 0.05 nor farther than the far plane allows.
void dollyCamera(Camera& camera, float factor);

// Moves eye and look-at together by `offset` in the camera's frame: x to the right, y up,
// z forward (along the view direction projected on the ground, so W/S keep the height).
void flyCamera(Camera& camera, const glm::vec3& offset);

// Turns the view direction about the eye (mouse look): the look-at point moves, the eye stays.
void lookCamera(Camera& camera, float yawDegrees, float pitchDegrees);

// Moves the camera as the held action does (isHeldAction) for `seconds` of holding, however
// long (issue 48: no cap per frame, so that a key held through slow frames moves at its rate;
// a tap is short because its press and release are timed, HeldKeys.h). Other actions leave
// the camera alone.
void applyHeldAction(Camera& camera, KeyAction action, double seconds);

}  // namespace manylights
