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

}  // namespace manylights
