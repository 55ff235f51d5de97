// Lights as packed for the GPU (render/scene/GpuScene.h: GpuLight), made by hand for the tests of
// the CPU's culling, grouping and shadow faces (TileCullingTest.cpp, StencilBatchesTest.cpp,
// ShadowFacesTest.cpp).
#pragma once

#include <cmath>

#include <glm/glm.hpp>

#include "render/scene/GpuScene.h"

namespace manylights::test {

// A white point light of range falloff reaching `radius`.
inline GpuLight pointLight(const glm::vec3& position, float radius)
{
    GpuLight light{};
    light.positionRadius = glm::vec4(position, radius);
    light.intensityExponent = glm::vec4(1.0f, 1.0f, 1.0f, 0.0f);
    light.attenuation = glm::vec4(radius, 0.0f, 0.0f, 1.0f);  // range falloff
    light.spotAxisCosCutoff = glm::vec4(0.0f, 0.0f, 0.0f, -2.0f);
    return light;
}

// The same, lighting the cone of half-angle `cutoffDegrees` about `axis` only.
inline GpuLight spotLight(const glm::vec3& position, float radius, const glm::vec3& axis, float cutoffDegrees)
{
    GpuLight light = pointLight(position, radius);
    light.spotAxisCosCutoff = glm::vec4(glm::normalize(axis), std::cos(glm::radians(cutoffDegrees)));
    return light;
}

}  // namespace manylights::test
