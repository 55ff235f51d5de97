#include "apps/view/CameraControls.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace manylights {

namespace {

constexpr float kPoleMarginDegrees = 5.0f;
constexpr float kMinimumDistance = 0.05f;

// `direction` turned by yaw about `up` and by pitch towards `up`, its angle from `up` kept
// within [margin, 180° − margin].
glm::vec3 turn(const glm::vec3& direction, const glm::vec3& up, float yawDegrees, float pitchDegrees)
{
    const float length = glm::length(direction);
    glm::vec3 d = direction / length;
    d = glm::vec3(glm::rotate(glm::mat4{1.0f}, glm::radians(yawDegrees), up) * glm::vec4(d, 0.0f));
    const float fromUp = glm::degrees(std::acos(std::clamp(glm::dot(d, up), -1.0f, 1.0f)));
    const float wanted = std::clamp(fromUp - pitchDegrees, kPoleMarginDegrees, 180.0f - kPoleMarginDegrees);
    const glm::vec3 side = glm::normalize(glm::cross(up, d));
    // Rotate about `side` so that the angle from up becomes `wanted`.
    d = glm::vec3(glm::rotate(glm::mat4{1.0f}, glm::radians(wanted - fromUp), side) * glm::vec4(d, 0.0f));
    return d * length;
}

}  // namespace

void orbitCamera(Camera& camera, float yawDegrees, float pitchDegrees)
{
    const glm::vec3 up = glm::normalize(camera.up);
    // The eye as seen from the look-at point: pitching it up raises the eye.
    camera.eye = camera.lookAt + turn(camera.eye - camera.lookAt, up, yawDegrees, pitchDegrees);
}

void dollyCamera(Camera& camera, float factor)
{
    const glm::vec3 offset = camera.eye - camera.lookAt;
    const float distance = glm::length(offset);
    const float wanted = std::clamp(distance * factor, kMinimumDistance, 0.9f * camera.farPlane);
    camera.eye = camera.lookAt + offset * (wanted / distance);
}

void flyCamera(Camera& camera, const glm::vec3& offset)
{
    const glm::vec3 up = glm::normalize(camera.up);
    const glm::vec3 view = camera.lookAt - camera.eye;
    glm::vec3 forward = view - glm::dot(view, up) * up;
    // Looking straight down: forward is the screen's up direction instead.
    forward =
        glm::length(forward) > 1e-6f ? glm::normalize(forward) : glm::normalize(glm::cross(up, glm::vec3{1, 0, 0}));
    const glm::vec3 right = glm::normalize(glm::cross(forward, up));
    const glm::vec3 move = offset.x * right + offset.y * up + offset.z * forward;
    camera.eye += move;
    camera.lookAt += move;
}

void lookCamera(Camera& camera, float yawDegrees, float pitchDegrees)
{
    const glm::vec3 up = glm::normalize(camera.up);
    camera.lookAt = camera.eye + turn(camera.lookAt - camera.eye, up, yawDegrees, pitchDegrees);
}

void applyHeldAction(Camera& camera, KeyAction action, double seconds)
{
    const auto dt = static_cast<float>(std::max(seconds, 0.0));
    const float turn = kOrbitDegreesPerSecond * dt;
    const float fly = kFlyFractionPerSecond * dt * glm::distance(camera.eye, camera.lookAt);
    switch (action) {
    case KeyAction::OrbitLeft: orbitCamera(camera, -turn, 0.0f); break;
    case KeyAction::OrbitRight: orbitCamera(camera, turn, 0.0f); break;
    case KeyAction::OrbitUp: orbitCamera(camera, 0.0f, turn); break;
    case KeyAction::OrbitDown: orbitCamera(camera, 0.0f, -turn); break;
    case KeyAction::DollyIn: dollyCamera(camera, std::pow(1.0f / kDollyPerSecond, dt)); break;
    case KeyAction::DollyOut: dollyCamera(camera, std::pow(kDollyPerSecond, dt)); break;
    case KeyAction::FlyForward: flyCamera(camera, {0.0f, 0.0f, fly}); break;
    case KeyAction::FlyBack: flyCamera(camera, {0.0f, 0.0f, -fly}); break;
    case KeyAction::FlyLeft: flyCamera(camera, {-fly, 0.0f, 0.0f}); break;
    case KeyAction::FlyRight: flyCamera(camera, {fly, 0.0f, 0.0f}); break;
    case KeyAction::FlyUp: flyCamera(camera, {0.0f, fly, 0.0f}); break;
    case KeyAction::FlyDown: flyCamera(camera, {0.0f, -fly, 0.0f}); break;
    // A positive yaw turns the view to the left (the mouse's drag to the right turns it right).
    case KeyAction::LookLeft: lookCamera(camera, turn, 0.0f); break;
    case KeyAction::LookRight: lookCamera(camera, -turn, 0.0f); break;
    case KeyAction::LookUp: lookCamera(camera, 0.0f, turn); break;
    case KeyAction::LookDown: lookCamera(camera, 0.0f, -turn); break;
    default: break;  // not a camera move
    }
}

}  // namespace manylights
