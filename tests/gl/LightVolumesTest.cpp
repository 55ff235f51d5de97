// The bounding meshes must enclose the region a light reaches (render/volumes/LightVolumes.h); these
// tests need no GL context.
#include <gtest/gtest.h>

#include <cmath>

#include "render/volumes/LightVolumes.h"
#include "scene/Falloff.h"

namespace manylights {
namespace {

// Signed distances of `point` to every face plane of a convex mesh: all negative inside.
float largestFaceDistance(const Mesh& mesh, const glm::vec3& point)
{
    float largest = -1e30f;
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
        const glm::vec3 a = mesh.vertices[mesh.indices[i]].position;
        const glm::vec3 b = mesh.vertices[mesh.indices[i + 1]].position;
        const glm::vec3 c = mesh.vertices[mesh.indices[i + 2]].position;
        const glm::vec3 outward = glm::normalize(glm::cross(b - a, c - a));
        largest = std::max(largest, glm::dot(outward, point - a));
    }
    return largest;
}

TEST(LightVolumes, SphereEnclosesTheUnitSphere)
{
    EXPECT_EQ(makeBoundingSphere().indices.size(), 20u * 3u);  // the icosahedron by default
    for (int subdivisions = 0; subdivisions <= 2; ++subdivisions) {
        const Mesh sphere = makeBoundingSphere(subdivisions);
        EXPECT_EQ(sphere.indices.size(), (20u << (2 * subdivisions)) * 3u);
        // Every face's plane is at distance ≥ 1 from the centre, facing outwards...
        EXPECT_LE(largestFaceDistance(sphere, glm::vec3(0.0f)), -1.0f + 1e-5f);
        // ...so points on the unit sphere, in every direction, are inside.
        for (int i = 0; i < 2000; ++i) {
            const float z = 1.0f - 2.0f * (static_cast<float>(i) + 0.5f) / 2000.0f;
            const float phi = static_cast<float>(i) * 2.39996323f;
            const float r = std::sqrt(1.0f - z * z);
            EXPECT_LE(largestFaceDistance(sphere, glm::vec3(r * std::cos(phi), r * std::sin(phi), z)), 1e-5f)
                << subdivisions << " subdivisions";
        }
    }
}

TEST(LightVolumes, ConeEnclosesTheLitRegionWithMargin)
{
    const Mesh cone = makeBoundingCone();
    // Unit space: the region is the part of the unit ball within 45° of +Z once the cone is
    // scaled by (tan 45°, tan 45°, 1) = identity. Sample its boundary: the cone's side out to
    // the ball, and the apex.
    for (int i = 0; i <= 50; ++i) {
        const float along = static_cast<float>(i) / 50.0f;  // distance from the apex
        for (int k = 0; k < 64; ++k) {
            const float angle = static_cast<float>(k) * 0.0981748f;
            const float s = along * std::sin(0.785398f);
            const glm::vec3 p(s * std::cos(angle), s * std::sin(angle), along * std::cos(0.785398f));
            // Strictly inside: a surface on the true cone's edge must not tie with a face.
            EXPECT_LT(largestFaceDistance(cone, p), -1e-5f * (1.0f + along)) << along << " " << angle;
        }
    }
}

TEST(LightVolumes, LightsAreGroupedByShape)
{
    std::vector<GpuLight> lights(5);
    lights[0].positionRadius.w = 3.0f;  // point
    lights[0].spotAxisCosCutoff.w = -2.0f;
    lights[1].positionRadius.w = 3.0f;  // spot, 30°: cone
    lights[1].spotAxisCosCutoff.w = std::cos(glm::radians(30.0f));
    lights[2].positionRadius.w = 3.0f;  // spot, 120°: sphere
    lights[2].spotAxisCosCutoff.w = std::cos(glm::radians(120.0f));
    lights[3].positionRadius.w = falloff::kUnboundedRadius;  // a = b = 0
    lights[4].positionRadius.w = 0.0f;                       // too dim to reach the threshold anywhere
    const LightVolumeGroups groups = groupLightVolumes(lights);
    EXPECT_EQ(groups.spheres, (std::vector<std::uint32_t>{0, 2}));
    EXPECT_EQ(groups.cones, (std::vector<std::uint32_t>{1}));
    EXPECT_EQ(groups.fullScreen, (std::vector<std::uint32_t>{3}));
}

// The stencil technique skips its stencil pass for spheres around the eye
// (render/volumes/VolumeTechniques.cpp), which is exact only where the eye is inside the bounding
// mesh: every eye the test accepts, at distances up to its margin, lies inside the icosahedron
// drawn for a light of that radius, and the eye on the sphere or beyond is refused.
TEST(LightVolumes, EyeInsideSphereVolumeOnlyWellInsideTheMesh)
{
    GpuLight light{};
    light.positionRadius = glm::vec4(1.0f, 2.0f, -3.0f, 4.0f);
    const glm::vec3 centre(light.positionRadius);
    const float radius = light.positionRadius.w;
    const Mesh sphere = makeBoundingSphere();
    for (int i = 0; i < 500; ++i) {
        const float z = 1.0f - 2.0f * (static_cast<float>(i) + 0.5f) / 500.0f;
        const float phi = static_cast<float>(i) * 2.39996323f;
        const float r = std::sqrt(1.0f - z * z);
        const glm::vec3 direction(r * std::cos(phi), r * std::sin(phi), z);
        for (const float fraction : {0.0f, 0.5f, 0.998f}) {
            const glm::vec3 eye = centre + fraction * radius * direction;
            ASSERT_TRUE(eyeInsideSphereVolume(light, eye)) << fraction;
            // The mesh of the light's instance: the unit mesh scaled by the radius, moved to the light.
            EXPECT_LT(largestFaceDistance(sphere, (eye - centre) / radius), 0.0f);
        }
        for (const float fraction : {1.0f, 1.5f})
            EXPECT_FALSE(eyeInsideSphereVolume(light, centre + fraction * radius * direction)) << fraction;
    }
}

}  // namespace
}  // namespace manylights
