// Animation (scene/Animation.h, scene/Revolution.h): each motion checked against its
// definition, and the default scene's invariants at many sampled times: everything standing
// on the floor stays on it, bouncing spheres touch it at each landing and never go below it.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "scene/Animation.h"
#include "scene/DefaultScene.h"
#include "scene/LightSets.h"
#include "scene/Revolution.h"
#include "scene/Transform.h"
#include "tests/unit/SharedDefaultScene.h"

#include <glm/gtc/matrix_transform.hpp>

namespace manylights {
namespace {

// Exact world bounds of an object at time t: every vertex through its animated transform.
Bounds boundsAt(const Scene& scene, const Object& object, double t)
{
    const glm::mat4 model = animatedTransform(object.transform, object.animation, t);
    Bounds bounds;
    for (const Vertex& vertex : scene.meshes[object.mesh].vertices)
        bounds.extend(glm::vec3(model * glm::vec4(vertex.position, 1.0f)));
    return bounds;
}

// Sampled times: irregular steps (so that no sample lines up with every period) over 30 s.
std::vector<double> sampleTimes()
{
    std::vector<double> times;
    for (double t = 0.0; t < 30.0; t += 0.2371)
        times.push_back(t);
    return times;
}

// float rounding of a product of a few transforms of values of order 10.
constexpr float kPositionTolerance = 1e-4f;

class DefaultSceneOverTime : public ::testing::Test {
protected:
    static const Scene& scene() { return test::sharedDefaultScene(); }
};

TEST_F(DefaultSceneOverTime, HasEveryKindOfMotion)
{
    int spinning = 0;
    int swaying = 0;
    int bouncing = 0;
    int dynamicSurfaces = 0;
    for (const Object& object : scene().objects) {
        if (object.revolution)
            ++dynamicSurfaces;
        if (!object.animation)
            continue;
        spinning += std::holds_alternative<SpinAnimation>(*object.animation);
        swaying += std::holds_alternative<SwayAnimation>(*object.animation);
        bouncing += std::holds_alternative<BounceAnimation>(*object.animation);
    }
    EXPECT_GE(spinning, 6);  // the bunnies
    EXPECT_GE(swaying, 6);   // the teapots
    EXPECT_GE(bouncing, 10);
    EXPECT_EQ(dynamicSurfaces, 1);
    EXPECT_TRUE(scene().lightMarkerRadius.has_value());
    int moving = 0;
    const std::vector<Light> lights = expandLights(scene());
    for (const Light& light : lights)
        moving += light.animation.has_value();
    EXPECT_EQ(moving, static_cast<int>(lights.size()));
}

TEST_F(DefaultSceneOverTime, ObjectsTouchButNeverEnterTheFloor)
{
    for (const Object& object : scene().objects) {
        if (object.name == "floor" || !object.animation)
            continue;
        const bool bounces = std::holds_alternative<BounceAnimation>(*object.animation);
        for (double t : sampleTimes()) {
            const Bounds bounds = boundsAt(scene(), object, t);
            if (bounces)
                ASSERT_GE(bounds.min.y, -kPositionTolerance) << object.name << " at t = " << t;
            else
                ASSERT_NEAR(bounds.min.y, 0.0f, kPositionTolerance) << object.name << " at t = " << t;
            // Nothing leaves the floor's ±20 square.
            ASSERT_GT(bounds.min.x, -20.0f) << object.name;
            ASSERT_LT(bounds.max.x, 20.0f) << object.name;
            ASSERT_GT(bounds.min.z, -20.0f) << object.name;
            ASSERT_LT(bounds.max.z, 20.0f) << object.name;
        }
        if (bounces) {
            // At each landing (s = 0: t = (k − phase) · period) the sphere touches the floor.
            const auto& bounce = std::get<BounceAnimation>(*object.animation);
            for (int k = 1; k < 5; ++k) {
                const double landing = (k - static_cast<double>(bounce.phase)) * bounce.period;
                EXPECT_NEAR(boundsAt(scene(), object, landing).min.y, 0.0f, kPositionTolerance) << object.name;
            }
        }
    }
}

TEST_F(DefaultSceneOverTime, SpinningAndSwayingKeepTheirFootprint)
{
    // The placement kept footprint circles apart at rest; a spinning object must stay inside
    // its circle, a swaying one within its circle plus the lean. Checked as: the horizontal
    // centre of the bounds moves by less than the sway at the top.
    for (const Object& object : scene().objects) {
        if (!object.animation || std::holds_alternative<BounceAnimation>(*object.animation))
            continue;
        const Bounds rest = boundsAt(scene(), object, 0.0);
        const glm::vec2 restCentre{0.5f * (rest.min.x + rest.max.x), 0.5f * (rest.min.z + rest.max.z)};
        const float restHalfDiagonal = 0.5f * glm::length(glm::vec2{rest.max.x - rest.min.x, rest.max.z - rest.min.z});
        for (double t : sampleTimes()) {
            const Bounds now = boundsAt(scene(), object, t);
            const glm::vec2 corners[4] = {
                {now.min.x, now.min.z}, {now.max.x, now.min.z}, {now.min.x, now.max.z}, {now.max.x, now.max.z}};
            float farthest = 0.0f;
            for (const glm::vec2& corner : corners)
                farthest = std::max(farthest, glm::distance(corner, restCentre));
            // The corners of the bounds of a turned object reach at most √2 times the circle.
            ASSERT_LT(farthest, 1.5f * restHalfDiagonal + 0.3f) << object.name << " at t = " << t;
        }
    }
}

TEST_F(DefaultSceneOverTime, SameTimeSameScene)
{
    const Scene other = makeDefaultScene();
    for (std::size_t i = 0; i < other.objects.size(); ++i) {
        const glm::mat4 a = animatedTransform(scene().objects[i].transform, scene().objects[i].animation, 7.25);
        const glm::mat4 b = animatedTransform(other.objects[i].transform, other.objects[i].animation, 7.25);
        ASSERT_EQ(a, b) << other.objects[i].name;
    }
}

TEST(Animation, BounceTouchesAtLandingPeaksAtHalfPeriodAndThinsWhenFast)
{
    const BounceAnimation bounce{2.0f, 1.0f, 0.0f, 0.4f, 0.0f};
    const glm::mat4 rest = glm::translate(glm::mat4{1.0f}, glm::vec3{3.0f, 0.5f, -1.0f});  // a unit sphere's centre
    const auto bottomAt = [&](double t) {
        return glm::vec3(animatedTransform(rest, bounce, t) * glm::vec4(0.0f, -0.5f, 0.0f, 1.0f));
    };
    EXPECT_NEAR(bottomAt(0.0).y, 0.0f, 1e-6f);
    EXPECT_NEAR(bottomAt(3.0).y, 0.0f, 1e-5f);
    EXPECT_NEAR(bottomAt(0.5).y, 2.0f, 1e-6f);   // 4·h·s·(1 − s) at s = ½
    EXPECT_NEAR(bottomAt(0.25).y, 1.5f, 1e-6f);  // 4·2·¼·¾
    EXPECT_NEAR(bottomAt(0.25).x, 3.0f, 1e-6f);  // the foot stays under the centre
    // Fastest at landing: X and Z scaled by 1 − squash, Y by its inverse.
    const glm::mat4 landing = animatedTransform(rest, bounce, 0.0);
    EXPECT_NEAR(glm::length(glm::vec3(landing[0])), 0.6f, 1e-6f);
    EXPECT_NEAR(glm::length(glm::vec3(landing[2])), 0.6f, 1e-6f);
    EXPECT_NEAR(glm::length(glm::vec3(landing[1])), 1.0f / 0.6f, 1e-5f);
    // Still at the top.
    const glm::mat4 top = animatedTransform(rest, bounce, 0.5);
    EXPECT_NEAR(glm::length(glm::vec3(top[0])), 1.0f, 1e-6f);
    // The phase shifts the cycle: with phase ½ the sphere starts at the top.
    const BounceAnimation shifted{2.0f, 1.0f, 0.5f, 0.4f, 0.0f};
    EXPECT_NEAR((animatedTransform(rest, shifted, 0.0) * glm::vec4(0.0f, -0.5f, 0.0f, 1.0f)).y, 2.0f, 1e-6f);
}

TEST(Animation, SwayKeepsTheBaseAndHeights)
{
    const SwayAnimation sway{{0.0f, 0.0f, 2.0f}, 0.25f, 0.5f, 0.0f, 0.0f};
    const glm::mat4 rest = composeTransform({1.0f, 0.0f, 1.0f}, {0.0f, 30.0f, 0.0f}, glm::vec3{1.0f});
    // At t = 0.5 s: sin(2π · 0.25) = 1, full lean along +Z.
    const glm::mat4 leaning = animatedTransform(rest, sway, 0.5);
    const glm::vec3 foot = glm::vec3(leaning * glm::vec4(0.3f, 0.0f, 0.2f, 1.0f));
    const glm::vec3 restFoot = glm::vec3(rest * glm::vec4(0.3f, 0.0f, 0.2f, 1.0f));
    EXPECT_NEAR(glm::distance(foot, restFoot), 0.0f, 1e-6f);
    const glm::vec3 top = glm::vec3(leaning * glm::vec4(0.0f, 2.0f, 0.0f, 1.0f));
    EXPECT_NEAR(top.y, 2.0f, 1e-6f);
    EXPECT_NEAR(top.z, 1.0f + 0.25f * 2.0f, 1e-6f);
    EXPECT_NEAR(top.x, 1.0f, 1e-6f);
    // Half a period later it leans the other way.
    const glm::vec3 back = glm::vec3(animatedTransform(rest, sway, 1.5) * glm::vec4(0.0f, 2.0f, 0.0f, 1.0f));
    EXPECT_NEAR(back.z, 1.0f - 0.5f, 1e-5f);
}

TEST(Animation, SpinTurnsAboutThePivotAndKeepsHeights)
{
    const SpinAnimation spin{{0.0f, 1.0f, 0.0f}, glm::vec3{2.0f, 0.0f, 0.0f}, 90.0f, 0.0f};
    const glm::mat4 rest{1.0f};
    // After 1 s, 90° about the vertical through (2, 0, 0): (3, 1, 0) goes to (2, 1, −1).
    const glm::vec3 moved = glm::vec3(animatedTransform(rest, spin, 1.0) * glm::vec4(3.0f, 1.0f, 0.0f, 1.0f));
    EXPECT_NEAR(moved.x, 2.0f, 1e-6f);
    EXPECT_NEAR(moved.y, 1.0f, 1e-6f);
    EXPECT_NEAR(moved.z, -1.0f, 1e-6f);
    const glm::vec3 pivot = glm::vec3(animatedTransform(rest, spin, 0.7) * glm::vec4(2.0f, 5.0f, 0.0f, 1.0f));
    EXPECT_NEAR(glm::distance(pivot, glm::vec3{2.0f, 5.0f, 0.0f}), 0.0f, 1e-6f);
}

TEST(Animation, OrbitAndDrift)
{
    const glm::vec3 centre{1.0f, 2.0f, 3.0f};
    const OrbitAnimation orbit{2.0f, 90.0f, 0.0f};
    const glm::vec3 quarter = animatedPosition(centre, orbit, 1.0);
    EXPECT_NEAR(quarter.x, 1.0f, 1e-6f);
    EXPECT_NEAR(quarter.y, 2.0f, 1e-6f);
    EXPECT_NEAR(quarter.z, 5.0f, 1e-6f);
    for (double t : sampleTimes())
        ASSERT_NEAR(glm::distance(animatedPosition(centre, orbit, t), centre), 2.0f, 1e-5f);

    const DriftAnimation drift{{1.0f, 0.5f, 2.0f}, {4.0f, 2.0f, 8.0f}, 0.0f};
    const glm::vec3 at1 = animatedPosition(centre, drift, 1.0);
    EXPECT_NEAR(at1.x, 1.0f + 1.0f, 1e-6f);                    // sin(2π·¼) = 1
    EXPECT_NEAR(at1.y, 2.0f, 1e-6f);                           // sin(2π·½) = 0
    EXPECT_NEAR(at1.z, 3.0f + 2.0f * std::sqrt(0.5f), 1e-6f);  // sin(2π·⅛)
    EXPECT_EQ(animatedPosition(centre, std::nullopt, 5.0), centre);
}

TEST(Animation, LightSetPhasesAreSpread)
{
    Scene scene;
    LightSet set;
    set.count = 3;
    set.boxMin = glm::vec3{0.0f};
    set.boxMax = glm::vec3{1.0f};
    set.animation = OrbitAnimation{1.0f, 10.0f, 5.0f};
    scene.lightSets.push_back(set);
    const std::vector<Light> lights = expandLights(scene);
    ASSERT_EQ(lights.size(), 3u);
    EXPECT_FLOAT_EQ(std::get<OrbitAnimation>(*lights[0].animation).phaseDegrees, 5.0f);
    EXPECT_NEAR(std::get<OrbitAnimation>(*lights[1].animation).phaseDegrees, 5.0f + 137.50776f, 1e-4f);
    EXPECT_NEAR(std::get<OrbitAnimation>(*lights[2].animation).phaseDegrees, 5.0f + 275.01553f, 1e-4f);
}

TEST(Revolution, AnalyticNormalIsTheCrossProductOfTheDerivatives)
{
    const RevolutionProfile profile;
    const float h = 1e-3f;
    for (double t : {0.0, 0.3, 1.7}) {
        for (float u : {0.05f, 0.3f, 0.77f}) {
            for (float v : {0.1f, 0.5f, 0.9f}) {
                const glm::vec3 du =
                    revolutionPosition(profile, u + h, v, t) - revolutionPosition(profile, u - h, v, t);
                const glm::vec3 dv =
                    revolutionPosition(profile, u, v + h, t) - revolutionPosition(profile, u, v - h, t);
                const glm::vec3 numeric = glm::normalize(glm::cross(dv, du));
                // Central differences with h = 1e-3 in float: about 1e-3 error in direction.
                EXPECT_NEAR(glm::distance(numeric, revolutionNormal(profile, u, v, t)), 0.0f, 3e-3f)
                    << "u " << u << " v " << v << " t " << t;
            }
        }
    }
}

TEST(Revolution, MeshIsTheSurfaceAtItsTime)
{
    const RevolutionProfile profile{0.5f, 2.0f, 0.2f, 1.0f, 0.5f};
    const Mesh mesh = makeRevolutionMesh(profile, 0.5, 8, 4);
    EXPECT_EQ(mesh.vertices.size(), 9u * 5u);
    EXPECT_EQ(mesh.indices.size(), 8u * 4u * 6u);
    // At t = 0.5 the wave has moved a quarter turn: r(v = 0) = 0.5 + 0.2 · sin(−π/2) = 0.3.
    EXPECT_NEAR(glm::length(mesh.vertices[0].position), 0.3f, 1e-6f);
    EXPECT_NEAR(mesh.vertices[4 * 9].position.y, 2.0f, 1e-6f);
    // The seam is duplicated: u = 0 and u = 1 at the same place.
    EXPECT_NEAR(glm::distance(mesh.vertices[0].position, mesh.vertices[8].position), 0.0f, 1e-6f);
}

}  // namespace
}  // namespace manylights
