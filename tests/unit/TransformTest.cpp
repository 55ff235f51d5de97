// Object transforms (docs/scene-format.md: M = T · Rz · Ry · Rx · S) and the bounds built on them.
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "scene/Scene.h"
#include "scene/Transform.h"

namespace manylights {
namespace {

// Single-precision trigonometry of 90-degree rotations leaves errors around 1e-7 per step.
constexpr float kTransformTolerance = 1e-5f;

void expectNear(const glm::vec3& actual, const glm::vec3& expected)
{
    EXPECT_NEAR(actual.x, expected.x, kTransformTolerance);
    EXPECT_NEAR(actual.y, expected.y, kTransformTolerance);
    EXPECT_NEAR(actual.z, expected.z, kTransformTolerance);
}

glm::vec3 apply(const glm::mat4& m, const glm::vec3& p) { return glm::vec3(m * glm::vec4(p, 1.0f)); }

TEST(Transform, IdentityByDefault)
{
    const glm::mat4 m = composeTransform(glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(1.0f));
    EXPECT_EQ(m, glm::mat4(1.0f));
}

// Worked by hand with Rx(90): (x, y, z) -> (x, -z, y), Ry(90): (x, y, z) -> (z, y, -x),
// Rz(90): (x, y, z) -> (-y, x, z).
TEST(Transform, ScaleThenXThenYThenZThenTranslate)
{
    const glm::mat4 m = composeTransform({1.0f, 2.0f, 3.0f}, {90.0f, 90.0f, 90.0f}, {2.0f, 1.0f, 1.0f});
    // (1,0,0) -S-> (2,0,0) -Rx-> (2,0,0) -Ry-> (0,0,-2) -Rz-> (0,0,-2) -T-> (1,2,1)
    expectNear(apply(m, {1.0f, 0.0f, 0.0f}), {1.0f, 2.0f, 1.0f});
    // (0,1,0) -S-> (0,1,0) -Rx-> (0,0,1) -Ry-> (1,0,0) -Rz-> (0,1,0) -T-> (1,3,3)
    expectNear(apply(m, {0.0f, 1.0f, 0.0f}), {1.0f, 3.0f, 3.0f});
    // (0,0,1) -S-> (0,0,1) -Rx-> (0,-1,0) -Ry-> (0,-1,0) -Rz-> (1,0,0) -T-> (2,2,3)
    expectNear(apply(m, {0.0f, 0.0f, 1.0f}), {2.0f, 2.0f, 3.0f});
    expectNear(apply(m, {0.0f, 0.0f, 0.0f}), {1.0f, 2.0f, 3.0f});
}

// The example above would not catch a wrong order unless other orders give other answers.
TEST(Transform, OtherOrdersGiveDifferentResults)
{
    const glm::mat4 m = composeTransform({1.0f, 2.0f, 3.0f}, {90.0f, 90.0f, 90.0f}, {2.0f, 1.0f, 1.0f});
    const glm::mat4 identity(1.0f);
    const glm::mat4 t = glm::translate(identity, {1.0f, 2.0f, 3.0f});
    const glm::mat4 rx = glm::rotate(identity, glm::radians(90.0f), {1.0f, 0.0f, 0.0f});
    const glm::mat4 ry = glm::rotate(identity, glm::radians(90.0f), {0.0f, 1.0f, 0.0f});
    const glm::mat4 rz = glm::rotate(identity, glm::radians(90.0f), {0.0f, 0.0f, 1.0f});
    const glm::mat4 s = glm::scale(identity, {2.0f, 1.0f, 1.0f});
    const glm::vec3 probe{0.3f, 0.5f, 0.7f};
    const glm::vec3 expected = apply(t * rz * ry * rx * s, probe);
    expectNear(apply(m, probe), expected);
    for (const glm::mat4& wrong :
         {t * rx * ry * rz * s, t * ry * rx * rz * s, t * rz * ry * rx, s * t * rz * ry * rx, rz * ry * rx * s * t}) {
        EXPECT_GT(glm::length(apply(wrong, probe) - expected), 0.1f);
    }
}

TEST(Transform, RotationAboutYIsCounterClockwiseSeenFromAbove)
{
    // Right-handed: +45 degrees about Y takes +X towards -Z.
    const glm::mat4 m = composeTransform(glm::vec3(0.0f), {0.0f, 45.0f, 0.0f}, glm::vec3(1.0f));
    const float h = std::sqrt(0.5f);
    expectNear(apply(m, {1.0f, 0.0f, 0.0f}), {h, 0.0f, -h});
}

TEST(Transform, NormalMatrixUnderNonUniformScale)
{
    // The plane x + y = 0 (normal (1,1,0)) becomes, after scaling x by 2, the plane through
    // (2,-1,0): its normal is (1,2,0)/sqrt(5), not the naively transformed (2,1,0).
    const glm::mat4 model = composeTransform(glm::vec3(5.0f), glm::vec3(0.0f), {2.0f, 1.0f, 1.0f});
    const glm::vec3 n = glm::normalize(normalMatrix(model) * glm::vec3(1.0f, 1.0f, 0.0f));
    expectNear(n, glm::vec3(1.0f, 2.0f, 0.0f) / std::sqrt(5.0f));
    const glm::vec3 tangent = glm::vec3(model * glm::vec4(1.0f, -1.0f, 0.0f, 0.0f));
    EXPECT_NEAR(glm::dot(n, tangent), 0.0f, kTransformTolerance);
    const glm::vec3 naive = glm::normalize(glm::mat3(model) * glm::vec3(1.0f, 1.0f, 0.0f));
    EXPECT_GT(std::abs(glm::dot(naive, tangent)), 0.5f);
}

TEST(Transform, NormalMatrixOfRigidTransformIsItsRotation)
{
    const glm::mat4 model = composeTransform({7.0f, -3.0f, 2.0f}, {10.0f, 20.0f, 30.0f}, glm::vec3(1.0f));
    const glm::mat3 n = normalMatrix(model);
    const glm::mat3 r(model);
    for (int c = 0; c < 3; ++c)
        for (int row = 0; row < 3; ++row)
            EXPECT_NEAR(n[c][row], r[c][row], kTransformTolerance);
}

TEST(Transform, NormalMatrixUnderMirroringScale)
{
    // Scaling by -1 in x mirrors the surface; the normal of the plane x = 0 stays along x.
    const glm::mat4 model = composeTransform(glm::vec3(0.0f), glm::vec3(0.0f), {-1.0f, 3.0f, 1.0f});
    expectNear(glm::normalize(normalMatrix(model) * glm::vec3(0.0f, 1.0f, 0.0f)), {0.0f, 1.0f, 0.0f});
    expectNear(normalMatrix(model) * glm::vec3(1.0f, 0.0f, 0.0f), {-1.0f, 0.0f, 0.0f});
}

Mesh unitCube()
{
    Mesh mesh;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? 1.0f : -1.0f, (corner & 2) ? 1.0f : -1.0f, (corner & 4) ? 1.0f : -1.0f);
        mesh.vertices.push_back({p, glm::vec3(0.0f, 1.0f, 0.0f), glm::vec2(0.0f)});
    }
    return mesh;
}

TEST(Bounds, MeshBounds)
{
    Mesh mesh;
    EXPECT_TRUE(mesh.bounds().empty());
    mesh.vertices.push_back({{1.0f, -2.0f, 3.0f}, glm::vec3(0.0f), glm::vec2(0.0f)});
    mesh.vertices.push_back({{-4.0f, 5.0f, 0.5f}, glm::vec3(0.0f), glm::vec2(0.0f)});
    const Bounds b = mesh.bounds();
    ASSERT_FALSE(b.empty());
    EXPECT_EQ(b.min, glm::vec3(-4.0f, -2.0f, 0.5f));
    EXPECT_EQ(b.max, glm::vec3(1.0f, 5.0f, 3.0f));
}

TEST(Bounds, WorldBoundsTransformsEveryCorner)
{
    Scene scene;
    EXPECT_TRUE(scene.worldBounds().empty());
    scene.meshes.push_back(unitCube());
    scene.meshes.push_back(Mesh{});  // empty meshes contribute nothing
    Object rotated;
    rotated.mesh = 0;
    rotated.transform = composeTransform({10.0f, 0.0f, 0.0f}, {0.0f, 45.0f, 0.0f}, glm::vec3(1.0f));
    Object scaled;
    scaled.mesh = 0;
    scaled.transform = composeTransform({0.0f, -5.0f, 0.0f}, glm::vec3(0.0f), {1.0f, 0.5f, 2.0f});
    Object nothing;
    nothing.mesh = 1;
    nothing.transform = composeTransform(glm::vec3(100.0f), glm::vec3(0.0f), glm::vec3(1.0f));
    scene.objects = {rotated, scaled, nothing};

    const Bounds b = scene.worldBounds();
    const float r = std::sqrt(2.0f);  // the rotated cube's corners reach sqrt(2) along x and z
    expectNear(b.min, {-1.0f, -5.5f, -2.0f});
    expectNear(b.max, {10.0f + r, 1.0f, 2.0f});
}

}  // namespace
}  // namespace manylights
