// The --shadow-lights ranking and the culling tests of the shadow-map passes (no GL).
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/ShadowSelection.h"

namespace manylights {
namespace {

// A camera at (0, 0, 10) looking at the origin, 90° vertical field of view, square image:
// the plane z = 0 shows x and y in [−10, 10].
glm::mat4 testCamera()
{
    return glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 100.0f) *
           glm::lookAt(glm::vec3(0, 0, 10), glm::vec3(0.0f), glm::vec3(0, 1, 0));
}

TEST(ShadowSelection, ScreenCoverageOfSpheres)
{
    const glm::mat4 camera = testCamera();
    // A sphere of radius 1 at the origin: its box's nearest face (z = 1, 9 from the eye)
    // spans ±1/9 of the half-screen in x and y: (2/9)² / 4 of the screen.
    EXPECT_NEAR(screenCoverage(glm::vec3(0.0f), 1.0f, camera), (2.0 / 9.0) * (2.0 / 9.0) / 4.0, 1e-6);
    // Half off the right edge: clipped to the screen.
    const double clipped = screenCoverage(glm::vec3(10, 0, 0), 1.0f, camera);
    EXPECT_GT(clipped, 0.0);
    EXPECT_LT(clipped, (2.0 / 9.0) * (2.0 / 9.0) / 4.0);
    // Entirely off screen, and behind the camera.
    EXPECT_EQ(screenCoverage(glm::vec3(30, 0, 0), 1.0f, camera), 0.0);
    // Around the camera, and unbounded: the whole screen.
    EXPECT_EQ(screenCoverage(glm::vec3(0, 0, 10), 1.0f, camera), 1.0);
    EXPECT_EQ(screenCoverage(glm::vec3(0.0f), 3.0e38f, camera), 1.0);
}

TEST(ShadowSelection, RanksByCoverageTimesIntensityWithTiesByIndex)
{
    const glm::mat4 camera = testCamera();
    const std::vector<ShadowCandidate> lights = {
        {glm::vec3(0.0f), 1.0f, 1.0f},      // 0: small, dim
        {glm::vec3(0.0f), 2.0f, 1.0f},      // 1: larger, so more coverage
        {glm::vec3(30, 0, 0), 5.0f, 9.0f},  // 2: bright but off screen: never chosen
        {glm::vec3(0.0f), 1.0f, 4.0f},      // 3: small but bright
        {glm::vec3(0.0f), 2.0f, 1.0f},      // 4: the same as 1: after it
        {glm::vec3(0.0f), 1.0f, 0.0f},      // 5: no intensity: never chosen
    };
    // Scores: 0: c1, 1: c2, 3: 4·c1, 4: c2, with c2 = coverage of radius 2 = (4/8)²/4
    // = 0.0625 and c1 = 0.0123: 3 (0.049) < 1 = 4 (0.0625).
    EXPECT_EQ(selectShadowLights(lights, camera, 10), (std::vector<std::size_t>{1, 4, 3, 0}));
    EXPECT_EQ(selectShadowLights(lights, camera, 2), (std::vector<std::size_t>{1, 4}));
    EXPECT_TRUE(selectShadowLights(lights, camera, 0).empty());
}

TEST(ShadowSelection, ObjectCullingAgainstSpheresAndCones)
{
    const Bounds box{glm::vec3(2, -1, -1), glm::vec3(4, 1, 1)};
    EXPECT_TRUE(boxIntersectsSphere(box, glm::vec3(0.0f), 2.0f));
    EXPECT_FALSE(boxIntersectsSphere(box, glm::vec3(0.0f), 1.9f));
    // A spot at the origin pointing along +x reaches the box; pointing along −x or +y it does
    // not (30° cone); a 120° cone is never culled beyond the sphere test.
    EXPECT_TRUE(boxMayIntersectCone(box, glm::vec3(0.0f), glm::vec3(1, 0, 0), 30.0f, 10.0f));
    EXPECT_FALSE(boxMayIntersectCone(box, glm::vec3(0.0f), glm::vec3(-1, 0, 0), 30.0f, 10.0f));
    EXPECT_FALSE(boxMayIntersectCone(box, glm::vec3(0.0f), glm::vec3(0, 1, 0), 30.0f, 10.0f));
    EXPECT_TRUE(boxMayIntersectCone(box, glm::vec3(0.0f), glm::vec3(-1, 0, 0), 120.0f, 10.0f));
    EXPECT_FALSE(boxMayIntersectCone(box, glm::vec3(0.0f), glm::vec3(1, 0, 0), 30.0f, 1.0f));
}

TEST(ShadowSelection, TransformedBoundsHoldTheTransformedCorners)
{
    const Bounds unit{glm::vec3(-1.0f), glm::vec3(1.0f)};
    const glm::mat4 m =
        glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(5, 0, 0)), glm::radians(45.0f), glm::vec3(0, 1, 0));
    const Bounds world = transformedBounds(unit, m);
    EXPECT_NEAR(world.min.x, 5.0f - std::sqrt(2.0f), 1e-5f);
    EXPECT_NEAR(world.max.x, 5.0f + std::sqrt(2.0f), 1e-5f);
    EXPECT_NEAR(world.min.y, -1.0f, 1e-5f);
    EXPECT_TRUE(transformedBounds(Bounds{}, m).empty());
}

}  // namespace
}  // namespace manylights
