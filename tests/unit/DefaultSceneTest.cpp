#include "scene/DefaultScene.h"

#include <cmath>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "tests/unit/SharedDefaultScene.h"

namespace manylights {
namespace {

// Exact world bounds: every vertex through the object's transform.
Bounds worldBoundsOf(const Scene& scene, const Object& object)
{
    Bounds bounds;
    for (const Vertex& vertex : scene.meshes[object.mesh].vertices)
        bounds.extend(glm::vec3(object.transform * glm::vec4(vertex.position, 1.0f)));
    return bounds;
}

class DefaultScene : public ::testing::Test {
protected:
    static const Scene& scene() { return test::sharedDefaultScene(); }
};

TEST_F(DefaultScene, IsWellFormed)
{
    EXPECT_EQ(scene().source, "<default scene>");
    std::set<std::string> names;
    for (const Object& object : scene().objects) {
        ASSERT_LT(object.mesh, scene().meshes.size());
        ASSERT_LT(object.material, scene().materials.size());
        EXPECT_FALSE(object.name.empty());
        EXPECT_TRUE(names.insert(object.name).second) << "duplicate name " << object.name;
    }
    std::set<std::string> meshNames;
    for (const Mesh& mesh : scene().meshes) {
        EXPECT_TRUE(meshNames.insert(mesh.name).second) << "duplicate mesh name " << mesh.name;
        EXPECT_FALSE(mesh.indices.empty()) << mesh.name;
        for (const Vertex& vertex : mesh.vertices)
            ASSERT_NEAR(glm::length(vertex.normal), 1.0f, 1e-5f) << mesh.name;
    }
    for (const Material& material : scene().materials) {
        EXPECT_GE(material.shininess, 1.0f);
        for (int c = 0; c < 3; ++c) {
            EXPECT_GE(material.diffuse[c], 0.0f);
            EXPECT_LE(material.diffuse[c], 1.0f);
        }
    }
    EXPECT_TRUE(scene().directional.has_value());
}

TEST_F(DefaultScene, HasManyObjectsIncludingModels)
{
    EXPECT_GE(scene().objects.size(), 100u);
    // The bunnies and teapots share one loaded mesh each.
    int models = 0;
    for (const Object& object : scene().objects) {
        const std::string& mesh = scene().meshes[object.mesh].name;
        models += mesh == "bunny" || mesh == "teapot" ? 1 : 0;
    }
    EXPECT_GE(models, 12);
}

TEST_F(DefaultScene, ObjectsRestOnTheFloorWithoutOverlapping)
{
    std::vector<Bounds> footprints;
    for (const Object& object : scene().objects) {
        const Bounds bounds = worldBoundsOf(scene(), object);
        if (object.name == "floor") {
            EXPECT_EQ(bounds.min.y, 0.0f);
            EXPECT_EQ(bounds.max.y, 0.0f);
            continue;
        }
        // float rounding of the transform
        EXPECT_NEAR(bounds.min.y, 0.0f, 1e-4f) << object.name;
        const float height = bounds.max.y - bounds.min.y;
        EXPECT_GT(height, 0.15f) << object.name;
        EXPECT_LT(height, 1.7f) << object.name;
        EXPECT_GE(bounds.min.x, -16.0f - 1e-4f) << object.name;
        EXPECT_LE(bounds.max.x, 16.0f + 1e-4f) << object.name;
        EXPECT_GE(bounds.min.z, -16.0f - 1e-4f) << object.name;
        EXPECT_LE(bounds.max.z, 16.0f + 1e-4f) << object.name;
        for (const Bounds& other : footprints) {
            const bool apart = bounds.max.x < other.min.x || other.max.x < bounds.min.x || bounds.max.z < other.min.z ||
                               other.max.z < bounds.min.z;
            EXPECT_TRUE(apart) << object.name << " overlaps another object";
        }
        footprints.push_back(bounds);
    }
}

TEST_F(DefaultScene, ObjectsAreSpreadOverTheFloor)
{
    // Spread in both X and Z, and not along a line: small correlation between them.
    double n = 0, sx = 0, sz = 0, sxx = 0, szz = 0, sxz = 0;
    for (const Object& object : scene().objects) {
        if (object.name == "floor")
            continue;
        const double x = object.transform[3].x;
        const double z = object.transform[3].z;
        n += 1;
        sx += x;
        sz += z;
        sxx += x * x;
        szz += z * z;
        sxz += x * z;
    }
    const double varianceX = sxx / n - (sx / n) * (sx / n);
    const double varianceZ = szz / n - (sz / n) * (sz / n);
    const double covariance = sxz / n - (sx / n) * (sz / n);
    // A uniform spread over ±16 has a standard deviation of about 9.
    EXPECT_GT(std::sqrt(varianceX), 6.0);
    EXPECT_GT(std::sqrt(varianceZ), 6.0);
    EXPECT_LT(std::abs(covariance / std::sqrt(varianceX * varianceZ)), 0.3);
}

TEST_F(DefaultScene, LightsAreOneLargeLightSet)
{
    int total = 0;
    for (const LightSet& set : scene().lightSets) {
        total += set.count;
        EXPECT_LT(set.range.lo, set.range.hi);
        EXPECT_LE(set.boxMin.y, set.boxMax.y);
    }
    EXPECT_GE(total, 200);
    EXPECT_GE(scene().lightSets.size(), 1u);
}

TEST_F(DefaultScene, CameraSeesTheCrowd)
{
    const Camera& camera = scene().camera;
    EXPECT_GT(camera.eye.y, 5.0f);
    EXPECT_LT(camera.nearPlane, camera.farPlane);
    // The farthest floor corner is within the far plane.
    EXPECT_LT(glm::distance(camera.eye, glm::vec3(20.0f, 0.0f, -20.0f)), camera.farPlane);
}

bool sameMesh(const Mesh& a, const Mesh& b)
{
    if (a.name != b.name || a.indices != b.indices || a.vertices.size() != b.vertices.size())
        return false;
    for (std::size_t i = 0; i < a.vertices.size(); ++i)
        if (a.vertices[i].position != b.vertices[i].position || a.vertices[i].normal != b.vertices[i].normal ||
            a.vertices[i].uv != b.vertices[i].uv)
            return false;
    return true;
}

TEST_F(DefaultScene, IsDeterministic)
{
    const Scene& a = scene();
    const Scene b = makeDefaultScene();
    ASSERT_EQ(a.objects.size(), b.objects.size());
    for (std::size_t i = 0; i < a.objects.size(); ++i) {
        EXPECT_EQ(a.objects[i].name, b.objects[i].name);
        EXPECT_EQ(a.objects[i].mesh, b.objects[i].mesh);
        EXPECT_EQ(a.objects[i].material, b.objects[i].material);
        EXPECT_EQ(a.objects[i].transform, b.objects[i].transform) << a.objects[i].name;
    }
    ASSERT_EQ(a.meshes.size(), b.meshes.size());
    for (std::size_t i = 0; i < a.meshes.size(); ++i)
        EXPECT_TRUE(sameMesh(a.meshes[i], b.meshes[i])) << a.meshes[i].name;
    ASSERT_EQ(a.materials.size(), b.materials.size());
    for (std::size_t i = 0; i < a.materials.size(); ++i) {
        EXPECT_EQ(a.materials[i].name, b.materials[i].name);
        EXPECT_EQ(a.materials[i].diffuse, b.materials[i].diffuse);
        EXPECT_EQ(a.materials[i].specular, b.materials[i].specular);
        EXPECT_EQ(a.materials[i].shininess, b.materials[i].shininess);
    }
    ASSERT_EQ(a.lightSets.size(), b.lightSets.size());
    for (std::size_t i = 0; i < a.lightSets.size(); ++i) {
        EXPECT_EQ(a.lightSets[i].count, b.lightSets[i].count);
        EXPECT_EQ(a.lightSets[i].seed, b.lightSets[i].seed);
    }
    EXPECT_EQ(a.camera.eye, b.camera.eye);
    EXPECT_EQ(a.camera.lookAt, b.camera.lookAt);
}

}  // namespace
}  // namespace manylights
