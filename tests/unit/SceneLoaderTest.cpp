// The scene file (docs/scene-format.md): the example scene read field by field, defaults, sharing of
// meshes and materials, and a table of bad scenes whose errors must name the exact position.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <map>
#include <unistd.h>

#include "core/Error.h"
#include "scene/Revolution.h"
#include "scene/SceneLoader.h"
#include "scene/Transform.h"

namespace manylights {
namespace {

namespace fs = std::filesystem;

const fs::path kSceneDir = fs::path(MANYLIGHTS_TEST_DATA_DIR) / "scene";

Scene parse(const std::string& json) { return parseScene(json, "scene.json", kSceneDir); }

// The message of the Error that parsing `json` throws; a test failure if it throws none.
std::string errorOf(const std::string& json)
{
    try {
        parse(json);
    } catch (const Error& e) {
        return e.what();
    }
    ADD_FAILURE() << "no error for " << json;
    return {};
}

std::string resolved(const std::string& relative) { return (kSceneDir / relative).lexically_normal().string(); }

void expectVec3(const glm::vec3& actual, const glm::vec3& expected)
{
    EXPECT_FLOAT_EQ(actual.x, expected.x);
    EXPECT_FLOAT_EQ(actual.y, expected.y);
    EXPECT_FLOAT_EQ(actual.z, expected.z);
}

void expectMat4Near(const glm::mat4& actual, const glm::mat4& expected)
{
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            EXPECT_NEAR(actual[c][r], expected[c][r], 1e-6f) << "column " << c << " row " << r;
}

// tests/data/scene/example.json is the contract's example scene with the glTF object left out
// (not supported yet) and the bunny replaced by a small tetrahedron of known bounds.
TEST(SceneLoader, ExampleSceneEveryField)
{
    const fs::path file = kSceneDir / "example.json";
    const Scene scene = loadSceneFile(file);
    EXPECT_EQ(scene.source, file.string());

    expectVec3(scene.camera.eye, {0.0f, 6.0f, 14.0f});
    expectVec3(scene.camera.lookAt, {0.0f, 0.0f, 0.0f});
    expectVec3(scene.camera.up, {0.0f, 1.0f, 0.0f});
    EXPECT_FLOAT_EQ(scene.camera.fovYDegrees, 45.0f);
    EXPECT_FLOAT_EQ(scene.camera.nearPlane, 0.1f);
    EXPECT_FLOAT_EQ(scene.camera.farPlane, 200.0f);

    expectVec3(scene.background, {0.0f, 0.0f, 0.0f});
    expectVec3(scene.ambient, {0.05f, 0.05f, 0.05f});
    ASSERT_TRUE(scene.directional.has_value());
    expectVec3(scene.directional->direction, {-1.0f, -2.0f, -1.0f});
    expectVec3(scene.directional->intensity, {0.4f, 0.4f, 0.4f});
    EXPECT_FALSE(scene.directional->shadows);
    EXPECT_EQ(scene.attenuationThreshold, 0.00390625f);

    ASSERT_EQ(scene.lights.size(), 3u);
    const Light& lamp = scene.lights[0];
    EXPECT_EQ(lamp.type, LightType::Point);
    EXPECT_EQ(lamp.name, "lamp");
    expectVec3(lamp.position, {0.0f, 1.0f, 0.0f});
    expectVec3(lamp.intensity, {1.0f, 0.9f, 0.8f});
    EXPECT_EQ(lamp.falloff, Falloff::Classic);
    EXPECT_FLOAT_EQ(lamp.attenuation.constant, 1.0f);
    EXPECT_FLOAT_EQ(lamp.attenuation.linear, 0.0f);
    EXPECT_FLOAT_EQ(lamp.attenuation.quadratic, 0.3f);

    const Light& ranged = scene.lights[1];
    EXPECT_EQ(ranged.type, LightType::Point);
    EXPECT_EQ(ranged.name, "lights[1]");
    expectVec3(ranged.position, {3.0f, 0.5f, 2.0f});
    expectVec3(ranged.intensity, {0.2f, 0.4f, 1.0f});
    EXPECT_EQ(ranged.falloff, Falloff::Range);
    EXPECT_FLOAT_EQ(ranged.range, 4.0f);

    const Light& spot = scene.lights[2];
    EXPECT_EQ(spot.type, LightType::Spot);
    EXPECT_EQ(spot.name, "s0");
    expectVec3(spot.position, {0.0f, 5.0f, 0.0f});
    expectVec3(spot.direction, {0.0f, -1.0f, 0.0f});
    EXPECT_FLOAT_EQ(spot.cutoffDegrees, 30.0f);
    EXPECT_FLOAT_EQ(spot.exponent, 8.0f);
    expectVec3(spot.intensity, {1.0f, 1.0f, 1.0f});
    EXPECT_EQ(spot.falloff, Falloff::Classic);
    EXPECT_FLOAT_EQ(spot.attenuation.constant, 1.0f);
    EXPECT_FLOAT_EQ(spot.attenuation.linear, 0.1f);
    EXPECT_FLOAT_EQ(spot.attenuation.quadratic, 0.05f);

    ASSERT_EQ(scene.lightSets.size(), 1u);
    const LightSet& set = scene.lightSets[0];
    EXPECT_EQ(set.count, 1024);
    EXPECT_EQ(set.seed, 7u);
    EXPECT_EQ(set.type, LightType::Point);
    expectVec3(set.boxMin, {-20.0f, 0.2f, -20.0f});
    expectVec3(set.boxMax, {20.0f, 2.0f, 20.0f});
    EXPECT_FLOAT_EQ(set.range.lo, 1.5f);
    EXPECT_FLOAT_EQ(set.range.hi, 3.0f);
    EXPECT_FLOAT_EQ(set.intensity.lo, 0.3f);
    EXPECT_FLOAT_EQ(set.intensity.hi, 1.0f);

    // Named materials in file order, then the bunny's inline one; no default is needed.
    ASSERT_EQ(scene.materials.size(), 3u);
    const Material& grey = scene.materials[0];
    EXPECT_EQ(grey.name, "grey");
    expectVec3(grey.diffuse, {0.7f, 0.7f, 0.7f});
    expectVec3(grey.specular, {0.0f, 0.0f, 0.0f});
    EXPECT_FLOAT_EQ(grey.shininess, 32.0f);
    expectVec3(grey.emissive, {0.0f, 0.0f, 0.0f});
    EXPECT_TRUE(grey.diffuseMap.empty());
    EXPECT_TRUE(grey.specularMap.empty());
    EXPECT_TRUE(grey.normalMap.empty());
    const Material& shiny = scene.materials[1];
    EXPECT_EQ(shiny.name, "shiny");
    expectVec3(shiny.diffuse, {0.8f, 0.1f, 0.1f});
    expectVec3(shiny.specular, {0.5f, 0.5f, 0.5f});
    EXPECT_FLOAT_EQ(shiny.shininess, 64.0f);
    expectVec3(shiny.emissive, {0.0f, 0.0f, 0.0f});
    EXPECT_EQ(shiny.diffuseMap, resolved("textures/brick.png"));
    EXPECT_TRUE(shiny.specularMap.empty());
    EXPECT_EQ(shiny.normalMap, resolved("textures/brick_n.png"));
    EXPECT_TRUE(fs::is_regular_file(shiny.normalMap));
    const Material& inlineMaterial = scene.materials[2];
    EXPECT_EQ(inlineMaterial.name, "/objects/2/material");
    expectVec3(inlineMaterial.diffuse, {0.2f, 0.6f, 0.2f});
    EXPECT_FLOAT_EQ(inlineMaterial.shininess, 32.0f);

    ASSERT_EQ(scene.objects.size(), 3u);
    ASSERT_EQ(scene.meshes.size(), 3u);
    const Object& floor = scene.objects[0];
    EXPECT_EQ(floor.name, "floor");
    EXPECT_EQ(floor.material, 0u);
    EXPECT_EQ(floor.transform, glm::mat4(1.0f));
    const Bounds floorBounds = scene.meshes[floor.mesh].bounds();
    EXPECT_NEAR(floorBounds.min.x, -20.0f, 1e-4f);
    EXPECT_NEAR(floorBounds.max.z, 20.0f, 1e-4f);
    EXPECT_NEAR(floorBounds.max.y - floorBounds.min.y, 0.0f, 1e-4f);

    const Object& ball = scene.objects[1];
    EXPECT_EQ(ball.name, "ball");
    EXPECT_EQ(ball.material, 1u);
    expectMat4Near(ball.transform, composeTransform({0.0f, 1.0f, 0.0f}, {0.0f, 45.0f, 0.0f}, glm::vec3(1.0f)));
    // +45 degrees about Y takes +X towards -Z; the translation lifts it by 1.
    const glm::vec3 probe = glm::vec3(ball.transform * glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
    EXPECT_NEAR(probe.x, std::sqrt(0.5f), 1e-6f);
    EXPECT_NEAR(probe.y, 1.0f, 1e-6f);
    EXPECT_NEAR(probe.z, -std::sqrt(0.5f), 1e-6f);
    const Bounds ballBounds = scene.meshes[ball.mesh].bounds();
    EXPECT_NEAR(ballBounds.max.y, 1.0f, 1e-4f);
    EXPECT_NEAR(ballBounds.min.y, -1.0f, 1e-4f);

    const Object& bunny = scene.objects[2];
    EXPECT_EQ(bunny.name, "bunny");
    EXPECT_EQ(bunny.material, 2u);
    EXPECT_EQ(bunny.transform, glm::mat4(1.0f));
    const Bounds tetra = scene.meshes[bunny.mesh].bounds();
    expectVec3(tetra.min, {-1.0f, 0.0f, -0.5f});
    expectVec3(tetra.max, {2.0f, 3.0f, 0.5f});
    EXPECT_NE(floor.mesh, ball.mesh);
    EXPECT_NE(ball.mesh, bunny.mesh);

    const Bounds world = scene.worldBounds();
    EXPECT_NEAR(world.min.x, -20.0f, 1e-4f);
    EXPECT_NEAR(world.max.x, 20.0f, 1e-4f);
    EXPECT_NEAR(world.min.y, 0.0f, 1e-4f);
    EXPECT_NEAR(world.max.y, 3.0f, 1e-4f);
}

TEST(SceneLoader, EmptySceneHasSpecDefaults)
{
    const Scene scene = parse("{}");
    EXPECT_EQ(scene.source, "scene.json");
    expectVec3(scene.background, {0.0f, 0.0f, 0.0f});
    expectVec3(scene.ambient, {0.0f, 0.0f, 0.0f});
    EXPECT_FALSE(scene.directional.has_value());
    EXPECT_EQ(scene.attenuationThreshold, 1.0f / 256.0f);
    expectVec3(scene.camera.eye, {0.0f, 6.0f, 14.0f});
    EXPECT_FLOAT_EQ(scene.camera.fovYDegrees, 45.0f);
    EXPECT_TRUE(scene.lights.empty());
    EXPECT_TRUE(scene.lightSets.empty());
    EXPECT_TRUE(scene.materials.empty());
    EXPECT_TRUE(scene.meshes.empty());
    EXPECT_TRUE(scene.objects.empty());
}

TEST(SceneLoader, DefaultMaterialAddedOnceAndMaterialDefaults)
{
    const Scene scene = parse(R"json({
        "materials": { "plain": {} },
        "objects": [
            { "mesh": { "primitive": "box", "size": [1, 2, 3] } },
            { "mesh": { "primitive": "box", "size": [1, 2, 3] }, "material": "plain" },
            { "mesh": { "primitive": "box", "size": [1, 2, 3] } }
        ] })json");
    ASSERT_EQ(scene.materials.size(), 2u);
    ASSERT_EQ(scene.objects.size(), 3u);
    EXPECT_EQ(scene.objects[0].name, "objects[0]");
    EXPECT_EQ(scene.objects[0].material, 1u);
    EXPECT_EQ(scene.objects[1].material, 0u);
    EXPECT_EQ(scene.objects[2].material, 1u);
    for (const Material& m : scene.materials) {
        expectVec3(m.diffuse, {0.8f, 0.8f, 0.8f});
        expectVec3(m.specular, {0.0f, 0.0f, 0.0f});
        EXPECT_FLOAT_EQ(m.shininess, 32.0f);
        expectVec3(m.emissive, {0.0f, 0.0f, 0.0f});
    }
    // Identical primitives share one mesh.
    EXPECT_EQ(scene.meshes.size(), 1u);
}

// `opacity` below 1 makes a material transparent (AlphaMode::Blend); 1, or none, opaque.
TEST(SceneLoader, OpacityBelowOneIsTransparent)
{
    const Scene scene = parse(R"json({ "materials": {
        "glass": { "diffuse": [0.2, 0.4, 0.8], "opacity": 0.3 },
        "solid": { "opacity": 1 },
        "plain": {} } })json");
    ASSERT_EQ(scene.materials.size(), 3u);
    std::map<std::string, const Material*> byName;
    for (const Material& m : scene.materials)
        byName[m.name] = &m;
    EXPECT_EQ(byName.at("glass")->alphaMode, AlphaMode::Blend);
    EXPECT_FLOAT_EQ(byName.at("glass")->opacity, 0.3f);
    EXPECT_EQ(byName.at("solid")->alphaMode, AlphaMode::Opaque);
    EXPECT_EQ(byName.at("plain")->alphaMode, AlphaMode::Opaque);
    EXPECT_FLOAT_EQ(byName.at("plain")->opacity, 1.0f);
}

TEST(SceneLoader, MeshesAreShared)
{
    const Scene scene = parse(R"json({ "objects": [
        { "mesh": { "primitive": "sphere", "radius": 1 } },
        { "mesh": { "primitive": "sphere", "radius": 1.0 } },
        { "mesh": { "primitive": "sphere", "radius": 2 } },
        { "mesh": { "primitive": "cylinder", "radius": 1, "height": 2 } },
        { "mesh": { "primitive": "cone", "radius": 1, "height": 2 } },
        { "mesh": { "primitive": "torus", "radius": 1, "tube": 0.25 } },
        { "mesh": { "primitive": "plane", "size": [1, 2] } },
        { "mesh": "models/tetra.obj" },
        { "mesh": "models/../models/tetra.obj" },
        { "mesh": "./models/tetra.obj" }
    ] })json");
    ASSERT_EQ(scene.objects.size(), 10u);
    EXPECT_EQ(scene.meshes.size(), 7u);
    EXPECT_EQ(scene.objects[0].mesh, scene.objects[1].mesh);
    EXPECT_NE(scene.objects[0].mesh, scene.objects[2].mesh);
    EXPECT_NE(scene.objects[3].mesh, scene.objects[4].mesh);  // same parameters, other primitive
    EXPECT_EQ(scene.objects[7].mesh, scene.objects[8].mesh);
    EXPECT_EQ(scene.objects[7].mesh, scene.objects[9].mesh);
    const Bounds sphere2 = scene.meshes[scene.objects[2].mesh].bounds();
    EXPECT_NEAR(sphere2.max.y, 2.0f, 1e-4f);
    const Bounds torus = scene.meshes[scene.objects[5].mesh].bounds();
    EXPECT_NEAR(torus.max.x, 1.25f, 1e-3f);
    EXPECT_NEAR(torus.max.y, 0.25f, 1e-3f);
}

TEST(SceneLoader, AmbientOcclusionSettings)
{
    // Off by default (docs/lighting.md has no occlusion term); the block turns it on unless it says
    // "enabled": false.
    EXPECT_FALSE(parse("{}").ssao.enabled);
    const Scene on = parse(R"json({"ssao": {"radius": 0.75, "strength": 2}})json");
    EXPECT_TRUE(on.ssao.enabled);
    EXPECT_FLOAT_EQ(on.ssao.radius, 0.75f);
    EXPECT_FLOAT_EQ(on.ssao.strength, 2.0f);
    const Scene defaults = parse(R"json({"ssao": {}})json");
    EXPECT_TRUE(defaults.ssao.enabled);
    EXPECT_FLOAT_EQ(defaults.ssao.radius, 0.5f);
    EXPECT_FLOAT_EQ(defaults.ssao.strength, 1.0f);
    EXPECT_FALSE(parse(R"json({"ssao": {"enabled": false, "radius": 1}})json").ssao.enabled);
}

TEST(SceneLoader, LightDefaultsAndOptionalKeys)
{
    const Scene scene = parse(R"json({
        "directional": { "direction": [0, -1, 0], "intensity": [1, 1, 1], "shadows": true },
        "lights": [
            { "type": "spot", "pos": [0, 0, 0], "intensity": [1, 1, 1], "direction": [1, 0, 0],
              "cutoff": 180, "range": 2 },
            { "type": "point", "pos": [0, 0, 0], "intensity": [0, 0, 0],
              "attenuation": { "quadratic": 0.5 } }
        ],
        "light_sets": [
            { "count": 0, "type": "spot", "min": [0, 0, 0], "max": [0, 0, 0], "range": [1, 1],
              "intensity": [0, 0] },
            { "count": 1e3, "seed": 4294967295, "type": "spot", "min": [0, 0, 0], "max": [1, 1, 1],
              "range": [1, 2], "range_reference_count": 4096, "intensity": [1, 2], "cutoff": 30,
              "exponent": [1, 2] }
        ] })json");
    ASSERT_TRUE(scene.directional.has_value());
    EXPECT_TRUE(scene.directional->shadows);
    ASSERT_EQ(scene.lights.size(), 2u);
    EXPECT_FLOAT_EQ(scene.lights[0].exponent, 0.0f);
    EXPECT_FLOAT_EQ(scene.lights[0].cutoffDegrees, 180.0f);
    EXPECT_EQ(scene.lights[0].falloff, Falloff::Range);
    EXPECT_EQ(scene.lights[1].falloff, Falloff::Classic);
    EXPECT_FLOAT_EQ(scene.lights[1].attenuation.constant, 1.0f);
    EXPECT_FLOAT_EQ(scene.lights[1].attenuation.linear, 0.0f);
    EXPECT_FLOAT_EQ(scene.lights[1].attenuation.quadratic, 0.5f);
    ASSERT_EQ(scene.lightSets.size(), 2u);
    EXPECT_EQ(scene.lightSets[0].seed, 0u);
    EXPECT_FLOAT_EQ(scene.lightSets[0].cutoffDegrees.lo, 20.0f);
    EXPECT_FLOAT_EQ(scene.lightSets[0].cutoffDegrees.hi, 45.0f);
    EXPECT_FLOAT_EQ(scene.lightSets[0].exponent.lo, 0.0f);
    EXPECT_FLOAT_EQ(scene.lightSets[0].exponent.hi, 8.0f);
    EXPECT_FALSE(scene.lightSets[0].rangeReferenceCount.has_value());
    EXPECT_EQ(scene.lightSets[1].count, 1000);
    EXPECT_EQ(scene.lightSets[1].rangeReferenceCount, std::optional<int>(4096));
    EXPECT_EQ(scene.lightSets[1].seed, 4294967295u);
    EXPECT_FLOAT_EQ(scene.lightSets[1].cutoffDegrees.lo, 30.0f);
    EXPECT_FLOAT_EQ(scene.lightSets[1].cutoffDegrees.hi, 30.0f);
    EXPECT_FLOAT_EQ(scene.lightSets[1].exponent.lo, 1.0f);
    EXPECT_FLOAT_EQ(scene.lightSets[1].exponent.hi, 2.0f);
}

TEST(SceneLoader, TransformForms)
{
    const Scene scene = parse(R"json({ "objects": [
        { "mesh": { "primitive": "sphere", "radius": 1 },
          "transform": { "matrix": [1, 0, 0, 0,  0, 2, 0, 0,  0, 0, 3, 0,  5, 6, 7, 1] } },
        { "mesh": { "primitive": "sphere", "radius": 1 }, "transform": { "scale": 2 } },
        { "mesh": { "primitive": "sphere", "radius": 1 }, "transform": { "scale": [1, -2, 3] } },
        { "mesh": { "primitive": "sphere", "radius": 1 },
          "transform": { "translate": [1, 2, 3], "rotate": [90, 90, 90], "scale": [2, 1, 1] } },
        { "mesh": { "primitive": "sphere", "radius": 1 }, "transform": {} }
    ] })json");
    ASSERT_EQ(scene.objects.size(), 5u);
    // Column-major: the last four numbers are the translation column.
    const glm::mat4& m = scene.objects[0].transform;
    EXPECT_EQ(m[3], glm::vec4(5.0f, 6.0f, 7.0f, 1.0f));
    EXPECT_EQ(m[1], glm::vec4(0.0f, 2.0f, 0.0f, 0.0f));
    EXPECT_EQ(m[2][2], 3.0f);
    EXPECT_EQ(scene.objects[1].transform,
              glm::mat4(glm::vec4(2, 0, 0, 0), glm::vec4(0, 2, 0, 0), glm::vec4(0, 0, 2, 0), glm::vec4(0, 0, 0, 1)));
    EXPECT_EQ(scene.objects[2].transform,
              glm::mat4(glm::vec4(1, 0, 0, 0), glm::vec4(0, -2, 0, 0), glm::vec4(0, 0, 3, 0), glm::vec4(0, 0, 0, 1)));
    // The hand-worked example of TransformTest: (0,1,0) lands on (1,3,3).
    const glm::vec4 p = scene.objects[3].transform * glm::vec4(0.0f, 1.0f, 0.0f, 1.0f);
    EXPECT_NEAR(p.x, 1.0f, 1e-5f);
    EXPECT_NEAR(p.y, 3.0f, 1e-5f);
    EXPECT_NEAR(p.z, 3.0f, 1e-5f);
    EXPECT_EQ(scene.objects[4].transform, glm::mat4(1.0f));
}

TEST(SceneLoader, MissingSceneFile)
{
    const fs::path missing = kSceneDir / "no-such-scene.json";
    try {
        loadSceneFile(missing);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), missing.string() + ": cannot open scene file: No such file or directory");
    }
    try {
        loadSceneFile(kSceneDir);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), kSceneDir.string() + ": cannot open scene file: it is a directory");
    }
}

TEST(SceneLoader, ErrorsInAFileNameTheFile)
{
    const fs::path dir = fs::temp_directory_path() / ("manylights-scene-test-" + std::to_string(::getpid()));
    fs::create_directories(dir / "textures");
    const fs::path file = dir / "bad.json";
    {
        std::FILE* out = std::fopen(file.c_str(), "wb");
        ASSERT_NE(out, nullptr);
        const std::string text =
            "{\n  \"ambient\": [0, 0, 0],\n  \"materials\": { \"m\": { \"normal_map\": \"textures/n.png\" } }\n}\n";
        std::fwrite(text.data(), 1, text.size(), out);
        std::fclose(out);
    }
    try {
        loadSceneFile(file);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()),
                  file.string() + ": /materials/m/normal_map: file not found: " + (dir / "textures/n.png").string());
    }
    {
        std::FILE* out = std::fopen((dir / "textures/n.png").c_str(), "wb");
        ASSERT_NE(out, nullptr);
        std::fclose(out);
    }
    const Scene scene = loadSceneFile(file);
    ASSERT_EQ(scene.materials.size(), 1u);
    EXPECT_EQ(scene.materials[0].normalMap, (dir / "textures/n.png").string());
    fs::remove_all(dir);
}

TEST(SceneLoader, AnimationsAreRead)
{
    const Scene scene = parse(R"json({
        "light_markers": {"radius": 0.1},
        "lights": [
            {"type": "point", "pos": [1, 2, 3], "intensity": [1, 1, 1], "range": 2,
             "animation": {"orbit": {"radius": 1.5, "speed": -20, "phase": 90}}},
            {"type": "point", "pos": [0, 1, 0], "intensity": [1, 1, 1], "range": 2,
             "animation": {"drift": {"amplitude": [1, 0.5, 2], "period": [3, 4, 5], "phase": 10}}}
        ],
        "light_sets": [ {"count": 3, "min": [0, 0, 0], "max": [1, 1, 1], "range": [1, 2], "intensity": [1, 1],
                         "animation": {"orbit": {}}} ],
        "objects": [
            {"mesh": {"primitive": "sphere", "radius": 1},
             "animation": {"bounce": {"height": 2, "period": 1.5, "phase": 0.25, "squash": 0.3, "base": -1}}},
            {"mesh": {"primitive": "box", "size": [1, 1, 1]},
             "animation": {"spin": {"axis": [0, 2, 0], "speed": 30, "phase": 45, "pivot": [1, 0, 1]}}},
            {"mesh": {"primitive": "box", "size": [1, 2, 1]},
             "animation": {"sway": {"direction": [0, 0, 1], "amplitude": 0.1, "frequency": 2, "phase": 30}}},
            {"mesh": {"primitive": "revolution", "radius": 0.6, "height": 2, "amplitude": 0.1, "waves": 2,
                      "speed": 0.25, "dynamic": true}},
            {"mesh": {"primitive": "revolution", "time": 0.5}}
        ]
    })json");
    ASSERT_TRUE(scene.lightMarkerRadius.has_value());
    EXPECT_FLOAT_EQ(*scene.lightMarkerRadius, 0.1f);
    const auto& orbit = std::get<OrbitAnimation>(*scene.lights[0].animation);
    EXPECT_FLOAT_EQ(orbit.radius, 1.5f);
    EXPECT_FLOAT_EQ(orbit.degreesPerSecond, -20.0f);
    EXPECT_FLOAT_EQ(orbit.phaseDegrees, 90.0f);
    const auto& drift = std::get<DriftAnimation>(*scene.lights[1].animation);
    expectVec3(drift.amplitude, {1.0f, 0.5f, 2.0f});
    expectVec3(drift.period, {3.0f, 4.0f, 5.0f});
    EXPECT_FLOAT_EQ(drift.phaseDegrees, 10.0f);
    ASSERT_TRUE(scene.lightSets[0].animation.has_value());
    EXPECT_FLOAT_EQ(std::get<OrbitAnimation>(*scene.lightSets[0].animation).radius, OrbitAnimation{}.radius);

    const auto& bounce = std::get<BounceAnimation>(*scene.objects[0].animation);
    EXPECT_FLOAT_EQ(bounce.height, 2.0f);
    EXPECT_FLOAT_EQ(bounce.period, 1.5f);
    EXPECT_FLOAT_EQ(bounce.phase, 0.25f);
    EXPECT_FLOAT_EQ(bounce.squash, 0.3f);
    EXPECT_FLOAT_EQ(bounce.base, -1.0f);
    const auto& spin = std::get<SpinAnimation>(*scene.objects[1].animation);
    expectVec3(spin.axis, {0.0f, 2.0f, 0.0f});
    EXPECT_FLOAT_EQ(spin.degreesPerSecond, 30.0f);
    EXPECT_FLOAT_EQ(spin.phaseDegrees, 45.0f);
    ASSERT_TRUE(spin.pivot.has_value());
    expectVec3(*spin.pivot, {1.0f, 0.0f, 1.0f});
    const auto& sway = std::get<SwayAnimation>(*scene.objects[2].animation);
    expectVec3(sway.direction, {0.0f, 0.0f, 1.0f});
    EXPECT_FLOAT_EQ(sway.amplitude, 0.1f);
    EXPECT_FLOAT_EQ(sway.frequency, 2.0f);
    EXPECT_FLOAT_EQ(sway.phaseDegrees, 30.0f);

    ASSERT_TRUE(scene.objects[3].revolution.has_value());
    EXPECT_FLOAT_EQ(scene.objects[3].revolution->radius, 0.6f);
    EXPECT_FLOAT_EQ(scene.objects[3].revolution->height, 2.0f);
    EXPECT_FLOAT_EQ(scene.objects[3].revolution->waves, 2.0f);
    EXPECT_FLOAT_EQ(scene.objects[3].revolution->speed, 0.25f);
    // The static surface is frozen at its time: its vertices are the CPU surface at t = 0.5.
    EXPECT_FALSE(scene.objects[4].revolution.has_value());
    const Mesh& frozen = scene.meshes[scene.objects[4].mesh];
    const Vertex& vertex = frozen.vertices[30];
    expectVec3(vertex.position, revolutionPosition(RevolutionProfile{}, vertex.uv.x, vertex.uv.y, 0.5));
}

// ---------------------------------------------------------------------------------------
// Bad scenes: each must fail with a one-line message that starts with the exact position
// (FILE:LINE:COLUMN for syntax, FILE: /json/pointer for everything else) and says what is wrong.

struct BadScene {
    const char* name;
    std::string json;
    std::string where;   // the message starts with "scene.json" + where
    std::string phrase;  // and contains this
};

std::ostream& operator<<(std::ostream& out, const BadScene& bad) { return out << bad.name; }

std::string sphereObject(const std::string& extra)
{
    return R"json({ "objects": [ { "mesh": { "primitive": "sphere", "radius": 1 })json" + extra + " } ] }";
}

std::string withLight(const std::string& light) { return R"json({ "lights": [ )json" + light + " ] }"; }

std::string withSet(const std::string& set) { return R"json({ "light_sets": [ )json" + set + " ] }"; }

std::string withMesh(const std::string& mesh) { return R"json({ "objects": [ { "mesh": )json" + mesh + " } ] }"; }

const std::string kPoint = R"json("type": "point", "pos": [0, 0, 0], "intensity": [1, 1, 1])json";
const std::string kSpot =
    R"json("type": "spot", "pos": [0, 0, 0], "intensity": [1, 1, 1], "direction": [0, -1, 0], "range": 1)json";
const std::string kSet =
    R"json("count": 4, "min": [0, 0, 0], "max": [1, 1, 1], "range": [1, 2], "intensity": [0, 1])json";

std::string tooManyObjects()
{
    std::string json = R"json({ "objects": [0)json";
    for (int i = 0; i < 1'000'000; ++i)
        json += ",0";
    return json + "] }";
}

const std::vector<BadScene> kBadScenes = {
    // Syntax: positions are 1-based line:column of the offending character.
    {"TrailingComma", R"json({"ambient": [0, 0, 0],})json", ":1:23: ", "unexpected '}'"},
    {"MissingCommaOnLine3", "{\n  \"camera\": {\n    \"eye\": [0, 1 2]\n  }\n}", ":3:18: ", "expected ']'"},
    {"EmptyText", "", ":1:1: ", "unexpected end of input"},
    {"UnterminatedString", "{\n  \"ambient\": \"abc\n}", ":2:18: ", "invalid string"},
    {"InvalidLiteral", "{\"directional\": {\"shadows\": tru }}", ":1:32: ", "invalid literal"},
    {"Comment", "{\n  // a comment\n}", ":2:3: ", "comments are not allowed in JSON"},
    {"BlockComment", "{\"ambient\": /* grey */ [0, 0, 0]}", ":1:13: ", "comments are not allowed in JSON"},
    {"TrailingGarbage", "{}\n{}", ":2:1: ", "expected end of input"},
    {"ColumnsCountCharactersNotBytes", "{\"ambient\": \"\xC3\xBC\",}", ":1:17: ", "unexpected '}'"},
    {"NumberTooLargeForDouble", "{\n  \"ambient\": [1, 1e400, 0]\n}", ":2:18: ", "number out of range: 1e400"},
    {"DuplicateKey", R"json({"materials": {"grey": {"diffuse": [1, 1, 1], "diffuse": [0, 0, 0]}}})json",
     ": /materials/grey/diffuse: ", "duplicate key 'diffuse'"},
    {"DuplicateKeyInArray", R"json({"lights": [{}, {"type": "point", "type": "spot"}]})json",
     ": /lights/1/type: ", "duplicate key 'type'"},

    // Top level.
    {"TopLevelArray", "[]", ": ", "the top level must be a JSON object, got an array"},
    {"TopLevelNumber", "42", ": ", "the top level must be a JSON object, got a number"},
    {"UnknownTopLevelKeyWithSuggestion", R"json({"lightsets": []})json",
     ": /lightsets: ", "unknown key 'lightsets' (did you mean 'light_sets'?)"},
    {"UnknownTopLevelKeyWithoutSuggestion", R"json({"animation": {}})json",
     ": /animation: ", "unknown key 'animation' (expected one of: camera, "},
    {"AttenuationThresholdZero", R"json({"attenuation_threshold": 0})json",
     ": /attenuation_threshold: ", "must be > 0, got 0"},
    {"BackgroundNegative", R"json({"background": [0, 0, -0.5]})json", ": /background/2: ", "must be >= 0, got -0.5"},
    {"AmbientNotAnArray", R"json({"ambient": 0.1})json",
     ": /ambient: ", "expected an array of 3 numbers, got a number"},
    {"AmbientOverflowsFloat", R"json({"ambient": [1e39, 0, 0]})json",
     ": /ambient/0: ", "1e+39 does not fit in a 32-bit float"},
    {"TooManyObjects", tooManyObjects(), ": /objects: ", "too many objects: 1000001 (at most 1000000)"},

    // Camera.
    {"CameraFovTooLarge", R"json({"camera": {"fov_y": 190}})json", ": /camera/fov_y: ", "must be in (0, 180), got 190"},
    {"CameraFovZero", R"json({"camera": {"fov_y": 0}})json", ": /camera/fov_y: ", "must be in (0, 180), got 0"},
    {"CameraNearZero", R"json({"camera": {"near": 0}})json", ": /camera/near: ", "must be > 0"},
    {"CameraFarBeforeNear", R"json({"camera": {"near": 5, "far": 2}})json",
     ": /camera/far: ", "must be greater than near (5), got 2"},
    {"CameraEyeIsLookAt", R"json({"camera": {"eye": [1, 2, 3], "look_at": [1, 2, 3]}})json",
     ": /camera/look_at: ", "look_at must differ from eye"},
    {"CameraUpParallel", R"json({"camera": {"eye": [0, 5, 0], "look_at": [0, 0, 0]}})json",
     ": /camera: ", "up is parallel to the view direction"},
    {"CameraUpParallelGiven", R"json({"camera": {"eye": [0, 0, 0], "look_at": [1, 0, 0], "up": [-2, 0, 0]}})json",
     ": /camera/up: ", "up is parallel"},
    {"CameraViewOverflows", R"json({"camera": {"eye": [3e38, 0, 0], "look_at": [-3e38, 0, 0]}})json",
     ": /camera/look_at: ", "look_at - eye overflows a float"},
    {"CameraUpZero", R"json({"camera": {"up": [0, 0, 0]}})json", ": /camera/up: ", "must be a non-zero vector"},
    {"CameraEyeTooShort", R"json({"camera": {"eye": [0, 1]}})json",
     ": /camera/eye: ", "expected an array of 3 numbers, got an array of 2 elements"},
    {"CameraEyeString", R"json({"camera": {"eye": [0, "1", 2]}})json",
     ": /camera/eye/1: ", "expected a number, got a string"},
    {"CameraTypo", R"json({"camera": {"lookat": [0, 0, 0]}})json",
     ": /camera/lookat: ", "unknown key 'lookat' (did you mean 'look_at'?)"},

    // Directional light.
    {"DirectionalMissingIntensity", R"json({"directional": {"direction": [0, -1, 0]}})json",
     ": /directional: ", "missing required key 'intensity'"},
    {"DirectionalShadowsNotBool",
     R"json({"directional": {"direction": [0, -1, 0], "intensity": [1, 1, 1], "shadows": "yes"}})json",
     ": /directional/shadows: ", "expected true or false, got a string"},
    {"DirectionalZero", R"json({"directional": {"direction": [0, 0, 0], "intensity": [1, 1, 1]}})json",
     ": /directional/direction: ", "must be a non-zero vector"},

    // Ambient occlusion.
    {"SsaoNotObject", R"json({"ssao": true})json", ": /ssao: ", "expected an object"},
    {"SsaoRadiusZero", R"json({"ssao": {"radius": 0}})json", ": /ssao/radius: ", "must be > 0, got 0"},
    {"SsaoStrengthNegative", R"json({"ssao": {"strength": -1}})json", ": /ssao/strength: ", "must be >= 0, got -1"},
    {"SsaoEnabledNotBool", R"json({"ssao": {"enabled": 1}})json",
     ": /ssao/enabled: ", "expected true or false, got a number"},
    {"SsaoTypo", R"json({"ssao": {"radious": 1}})json", ": /ssao/radious: ", "unknown key 'radious'"},

    // Lights.
    {"LightsNotArray", R"json({"lights": {}})json", ": /lights: ", "expected an array, got an object"},
    {"LightMissingType", withLight(R"json({"pos": [0, 0, 0], "intensity": [1, 1, 1], "range": 1})json"),
     ": /lights/0: ", "missing required key 'type'"},
    {"LightTypeSpotlight", withLight(R"json({"type": "spotlight"})json"),
     ": /lights/0/type: ", "light type must be 'point' or 'spot', got 'spotlight' (did you mean 'spot'?)"},
    {"LightBothFalloffs", withLight("{" + kPoint + R"json(, "range": 1, "attenuation": {"constant": 1}})json"),
     ": /lights/0: ", "has both 'attenuation' and 'range'"},
    {"LightNoFalloff", withLight("{" + kPoint + "}"), ": /lights/0: ", "give exactly one of 'attenuation' or 'range'"},
    {"LightRangeZero", withLight("{" + kPoint + R"json(, "range": 0})json"),
     ": /lights/0/range: ", "must be > 0, got 0"},
    {"LightAttenuationAllZero",
     withLight("{" + kPoint + R"json(, "attenuation": {"constant": 0, "linear": 0, "quadratic": 0}})json"),
     ": /lights/0/attenuation: ", "must not all be zero"},
    {"LightAttenuationNegative", withLight("{" + kPoint + R"json(, "attenuation": {"linear": -0.1}})json"),
     ": /lights/0/attenuation/linear: ", "must be >= 0, got -0.1"},
    {"LightAttenuationTypo", withLight("{" + kPoint + R"json(, "attenuation": {"quadratc": 1}})json"),
     ": /lights/0/attenuation/quadratc: ", "(did you mean 'quadratic'?)"},
    {"LightIntensityNegative",
     withLight(R"json({"type": "point", "pos": [0, 0, 0], "intensity": [1, -1, 1], "range": 1})json"),
     ": /lights/0/intensity/1: ", "must be >= 0, got -1"},
    {"LightPosMissing", withLight(R"json({"type": "point", "intensity": [1, 1, 1], "range": 1})json"),
     ": /lights/0: ", "missing required key 'pos'"},
    {"LightPositionInsteadOfPos", withLight("{" + kPoint + R"json(, "range": 1, "position": [0, 0, 0]})json"),
     ": /lights/0/position: ", "unknown key 'position' (did you mean 'pos'?)"},
    {"LightNameNotString", withLight("{" + kPoint + R"json(, "range": 1, "name": 3})json"),
     ": /lights/0/name: ", "expected a string, got a number"},
    {"SpotCutoffTooLarge",
     withLight("{" + kPoint + R"json(, "range": 1}, {)json" + kPoint + R"json(, "range": 1}, {)json" + kSpot +
               R"json(, "cutoff": 190})json"),
     ": /lights/2/cutoff: ", "must be in (0, 180], got 190"},
    {"SpotCutoffZero", withLight("{" + kSpot + R"json(, "cutoff": 0})json"),
     ": /lights/0/cutoff: ", "must be in (0, 180], got 0"},
    {"SpotCutoffMissing", withLight("{" + kSpot + "}"), ": /lights/0: ", "missing required key 'cutoff'"},
    {"SpotDirectionMissing",
     withLight(R"json({"type": "spot", "pos": [0, 0, 0], "intensity": [1, 1, 1], "range": 1, "cutoff": 30})json"),
     ": /lights/0: ", "missing required key 'direction'"},
    {"SpotDirectionZero",
     withLight(R"json({"type": "spot", "pos": [0, 0, 0], "intensity": [1, 1, 1], "range": 1, "cutoff": 30,
                       "direction": [0, 0, 0]})json"),
     ": /lights/0/direction: ", "must be a non-zero vector"},
    {"SpotExponentNegative", withLight("{" + kSpot + R"json(, "cutoff": 30, "exponent": -1})json"),
     ": /lights/0/exponent: ", "must be >= 0, got -1"},
    {"PointWithCutoff", withLight("{" + kPoint + R"json(, "range": 1, "cutoff": 30})json"),
     ": /lights/0/cutoff: ", "'cutoff' applies only to spot lights"},

    // Light sets.
    {"SetCountNegative", withSet(R"json({"count": -1})json"),
     ": /light_sets/0/count: ", "must be in [0, 16777216], got -1"},
    {"SetCountFraction", withSet(R"json({"count": 1.5})json"),
     ": /light_sets/0/count: ", "expected an integer, got 1.5"},
    {"SetCountTooLarge", withSet(R"json({"count": 20000000})json"),
     ": /light_sets/0/count: ", "must be in [0, 16777216], got 20000000"},
    {"SetCountString", withSet(R"json({"count": "8"})json"),
     ": /light_sets/0/count: ", "expected an integer, got a string"},
    {"SetCountsAddUpTooHigh",
     R"json({"light_sets": [
         {"count": 10000000, "min": [0, 0, 0], "max": [1, 1, 1], "range": [1, 2], "intensity": [0, 1]},
         {"count": 10000000, "min": [0, 0, 0], "max": [1, 1, 1], "range": [1, 2], "intensity": [0, 1]}]})json",
     ": /light_sets/1/count: ", "counts add up to 20000000, more than 16777216"},
    {"SetSeedNegative", withSet("{" + kSet + R"json(, "seed": -7})json"),
     ": /light_sets/0/seed: ", "must be in [0, 4294967295], got -7"},
    {"SetMinAboveMax",
     withSet(R"json({"count": 4, "min": [0, 3, 0], "max": [1, 2, 1], "range": [1, 2], "intensity": [0, 1]})json"),
     ": /light_sets/0/max/1: ", "must be >= min on every axis, got max.y 2 < min.y 3"},
    {"SetRangeReversed",
     withSet(R"json({"count": 4, "min": [0, 0, 0], "max": [1, 1, 1], "range": [3, 1], "intensity": [0, 1]})json"),
     ": /light_sets/0/range: ", "interval must have lo <= hi, got [3, 1]"},
    {"SetRangeZero",
     withSet(R"json({"count": 4, "min": [0, 0, 0], "max": [1, 1, 1], "range": [0, 1], "intensity": [0, 1]})json"),
     ": /light_sets/0/range/0: ", "must be > 0, got 0"},
    {"SetRangeNumber",
     withSet(R"json({"count": 4, "min": [0, 0, 0], "max": [1, 1, 1], "range": 2, "intensity": [0, 1]})json"),
     ": /light_sets/0/range: ", "expected an interval [lo, hi] of 2 numbers, got a number"},
    {"SetIntensityNegative",
     withSet(R"json({"count": 4, "min": [0, 0, 0], "max": [1, 1, 1], "range": [1, 2], "intensity": [-1, 1]})json"),
     ": /light_sets/0/intensity/0: ", "must be >= 0, got -1"},
    {"SetMissingMin", withSet(R"json({"count": 4})json"), ": /light_sets/0: ", "missing required key 'min'"},
    {"SetRangeReferenceZero", withSet("{" + kSet + R"json(, "range_reference_count": 0})json"),
     ": /light_sets/0/range_reference_count: ", "must be in [1, 16777216], got 0"},
    {"SetRangeReferenceFraction", withSet("{" + kSet + R"json(, "range_reference_count": 2.5})json"),
     ": /light_sets/0/range_reference_count: ", "expected an integer, got 2.5"},
    {"SetRangeReferenceString", withSet("{" + kSet + R"json(, "range_reference_count": "1024"})json"),
     ": /light_sets/0/range_reference_count: ", "expected an integer, got a string"},
    {"SetRangeReferenceTooLarge", withSet("{" + kSet + R"json(, "range_reference_count": 20000000})json"),
     ": /light_sets/0/range_reference_count: ", "must be in [1, 16777216], got 20000000"},
    {"SpotSetCutoffTooLarge", withSet("{" + kSet + R"json(, "type": "spot", "cutoff": [10, 200]})json"),
     ": /light_sets/0/cutoff/1: ", "must be in (0, 180], got 200"},
    {"SpotSetExponentString", withSet("{" + kSet + R"json(, "type": "spot", "exponent": "high"})json"),
     ": /light_sets/0/exponent: ", "expected a number or an interval [lo, hi], got a string"},
    {"PointSetWithExponent", withSet("{" + kSet + R"json(, "exponent": 2})json"),
     ": /light_sets/0/exponent: ", "'exponent' applies only to spot light sets"},
    {"SetTypeArea", withSet("{" + kSet + R"json(, "type": "area"})json"),
     ": /light_sets/0/type: ", "light set type must be 'point' or 'spot', got 'area'"},

    // Materials.
    {"MaterialsArray", R"json({"materials": []})json", ": /materials: ", "expected an object, got an array"},
    {"MaterialShininessBelowOne", R"json({"materials": {"m": {"shininess": 0.5}}})json",
     ": /materials/m/shininess: ", "must be >= 1, got 0.5"},
    {"MaterialTypo", R"json({"materials": {"m": {"difuse": [1, 1, 1]}}})json",
     ": /materials/m/difuse: ", "unknown key 'difuse' (did you mean 'diffuse'?)"},
    {"MaterialEmissiveNegative", R"json({"materials": {"m": {"emissive": [0, -1, 0]}}})json",
     ": /materials/m/emissive/1: ", "must be >= 0"},
    {"MaterialNameNeedsPointerEscape", R"json({"materials": {"a/b~c": {"shininess": 0}}})json",
     ": /materials/a~1b~0c/shininess: ", "must be >= 1"},
    {"TextureMissing", R"json({"materials": {"m": {"diffuse_map": "textures/missing.png"}}})json",
     ": /materials/m/diffuse_map: ", "file not found: " + resolved("textures/missing.png")},
    {"TextureIsDirectory", R"json({"materials": {"m": {"specular_map": "textures"}}})json",
     ": /materials/m/specular_map: ", "not a regular file"},
    {"TextureEmptyPath", R"json({"materials": {"m": {"normal_map": ""}}})json",
     ": /materials/m/normal_map: ", "expected a file path, got an empty string"},
    {"OpacityAboveOne", R"json({"materials": {"m": {"opacity": 1.5}}})json",
     ": /materials/m/opacity: ", "must be in [0, 1], got 1.5"},
    {"OpacityNegative", R"json({"materials": {"m": {"opacity": -0.1}}})json",
     ": /materials/m/opacity: ", "must be in [0, 1], got -0.1"},
    {"NormalScaleNotANumber", R"json({"materials": {"m": {"normal_scale": "2"}}})json",
     ": /materials/m/normal_scale: ", "expected a number, got a string"},

    // Objects and meshes.
    {"ObjectsNotArray", R"json({"objects": {}})json", ": /objects: ", "expected an array, got an object"},
    {"ObjectMissingMesh", R"json({"objects": [{"name": "x"}]})json", ": /objects/0: ", "missing required key 'mesh'"},
    {"ObjectUnknownMaterial",
     R"json({"materials": {"grey": {}},
             "objects": [{"mesh": {"primitive": "sphere", "radius": 1}, "material": "gray"}]})json",
     ": /objects/0/material: ", "unknown material 'gray' (did you mean 'grey'?)"},
    {"ObjectMaterialWithoutMaterials", sphereObject(R"json(, "material": "grey")json"),
     ": /objects/0/material: ", "unknown material 'grey' (the scene's 'materials' defines none)"},
    {"ObjectMaterialNumber", sphereObject(R"json(, "material": 3)json"),
     ": /objects/0/material: ", "expected a material name or a material object, got a number"},
    {"ObjectInlineMaterialBad", sphereObject(R"json(, "material": {"shininess": 0})json"),
     ": /objects/0/material/shininess: ", "must be >= 1, got 0"},
    {"MeshGltfMissing", withMesh(R"json("models/helmet.gltf")json"),
     ": /objects/0/mesh: ", "file not found: " + resolved("models/helmet.gltf")},
    {"MeshGlbMissing", withMesh(R"json("models/helmet.GLB")json"),
     ": /objects/0/mesh: ", "file not found: " + resolved("models/helmet.GLB")},
    // A model from a folder a Debian package installs: the message names the package.
    {"MeshFromMissingPackage", withMesh(R"json("/usr/share/assimp/models/glTF2/NoSuchModel/NoSuchModel.gltf")json"),
     ": /objects/0/mesh: ",
     "file not found: /usr/share/assimp/models/glTF2/NoSuchModel/NoSuchModel.gltf (installed by the Debian package "
     "assimp-testmodels: apt-get install assimp-testmodels, or scripts/setup.sh)"},
    {"MeshPly", withMesh(R"json("models/bunny.ply")json"),
     ": /objects/0/mesh: ", "unsupported mesh file type '.ply' (expected .obj, .gltf or .glb)"},
    {"MeshObjMissing", withMesh(R"json("models/nothere.obj")json"),
     ": /objects/0/mesh: ", "file not found: " + resolved("models/nothere.obj")},
    {"MeshObjBroken", withMesh(R"json("models/broken.obj")json"), ": /objects/0/mesh: ", "broken.obj"},
    {"MeshNumber", withMesh("7"),
     ": /objects/0/mesh: ", "expected a mesh file path or a primitive object, got a number"},
    {"PrimitiveUnknown", withMesh(R"json({"primitive": "sphre", "radius": 1})json"),
     ": /objects/0/mesh/primitive: ", "unknown primitive 'sphre' (did you mean 'sphere'?)"},
    {"PrimitiveMissing", withMesh(R"json({"radius": 1})json"),
     ": /objects/0/mesh: ", "missing required key 'primitive'"},
    {"SphereRadiusZero", withMesh(R"json({"primitive": "sphere", "radius": 0})json"),
     ": /objects/0/mesh/radius: ", "must be > 0, got 0"},
    {"SphereWithSize", withMesh(R"json({"primitive": "sphere", "size": [1, 1, 1]})json"),
     ": /objects/0/mesh/size: ", "unknown key 'size' (expected one of: primitive, radius)"},
    {"PlaneSizeWrongLength", withMesh(R"json({"primitive": "plane", "size": [1]})json"),
     ": /objects/0/mesh/size: ", "expected an array of 2 numbers, got an array of 1 element"},
    {"BoxSizeNegative", withMesh(R"json({"primitive": "box", "size": [1, -1, 1]})json"),
     ": /objects/0/mesh/size/1: ", "must be > 0, got -1"},
    {"TorusMissingTube", withMesh(R"json({"primitive": "torus", "radius": 1})json"),
     ": /objects/0/mesh: ", "missing required key 'tube'"},
    {"ConeHeightNegative", withMesh(R"json({"primitive": "cone", "radius": 1, "height": -2})json"),
     ": /objects/0/mesh/height: ", "must be > 0, got -2"},

    // Transforms.
    {"TransformMatrixAndTranslate",
     sphereObject(R"json(, "transform": {"translate": [1, 0, 0], "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]})json"),
     ": /objects/0/transform: ", "give either 'matrix' or 'translate'/'rotate'/'scale', not both"},
    {"TransformMatrixShort", sphereObject(R"json(, "transform": {"matrix": [1, 0, 0]})json"),
     ": /objects/0/transform/matrix: ", "expected an array of 16 numbers, got an array of 3 elements"},
    {"TransformMatrixRowMajor",
     sphereObject(R"json(, "transform": {"matrix": [1,0,0,5, 0,1,0,6, 0,0,1,7, 0,0,0,1]})json"),
     ": /objects/0/transform/matrix: ", "must be affine"},
    {"TransformMatrixSingular",
     sphereObject(R"json(, "transform": {"matrix": [1,0,0,0, 0,0,0,0, 0,0,1,0, 0,0,0,1]})json"),
     ": /objects/0/transform/matrix: ", "is singular"},
    {"TransformScaleZero", sphereObject(R"json(, "transform": {"scale": 0})json"),
     ": /objects/0/transform/scale: ", "must be non-zero, got 0"},
    {"TransformScaleComponentZero", sphereObject(R"json(, "transform": {"scale": [1, 0, 1]})json"),
     ": /objects/0/transform/scale/1: ", "must be non-zero, got 0"},
    {"TransformScaleString", sphereObject(R"json(, "transform": {"scale": "2"})json"),
     ": /objects/0/transform/scale: ", "expected a number or an array of 3 numbers, got a string"},
    {"TransformRotateShort", sphereObject(R"json(, "transform": {"rotate": [0, 90]})json"),
     ": /objects/0/transform/rotate: ", "expected an array of 3 numbers, got an array of 2 elements"},
    {"TransformTypo", sphereObject(R"json(, "transform": {"rotation": [0, 90, 0]})json"),
     ": /objects/0/transform/rotation: ", "(did you mean 'rotate'?)"},
    {"TransformTranslateHuge", sphereObject(R"json(, "transform": {"translate": [0, 1e300, 0]})json"),
     ": /objects/0/transform/translate/1: ", "number out of range"},
    // Animation (docs/scene-format.md "Animation").
    {"AnimationNotAnObject", sphereObject(R"json(, "animation": "spin")json"),
     ": /objects/0/animation: ", "expected an object, got a string"},
    {"AnimationTwoKinds", sphereObject(R"json(, "animation": {"spin": {}, "sway": {}})json"),
     ": /objects/0/animation: ", "expected exactly one animation kind (one of: spin, sway, bounce), got 2 keys"},
    {"AnimationUnknownKind", sphereObject(R"json(, "animation": {"spinn": {}})json"),
     ": /objects/0/animation/spinn: ", "unknown animation 'spinn' (did you mean 'spin'?)"},
    {"AnimationLightKindOnObject", sphereObject(R"json(, "animation": {"orbit": {}})json"),
     ": /objects/0/animation/orbit: ", "unknown animation 'orbit'"},
    {"AnimationUnknownKey", sphereObject(R"json(, "animation": {"spin": {"sped": 3}})json"),
     ": /objects/0/animation/spin/sped: ", "(did you mean 'speed'?)"},
    {"AnimationSpinSpeedString", sphereObject(R"json(, "animation": {"spin": {"speed": "fast"}})json"),
     ": /objects/0/animation/spin/speed: ", "expected a number, got a string"},
    {"AnimationSpinAxisZero", sphereObject(R"json(, "animation": {"spin": {"axis": [0, 0, 0]}})json"),
     ": /objects/0/animation/spin/axis: ", "must be a non-zero vector"},
    {"AnimationBouncePeriodNegative", sphereObject(R"json(, "animation": {"bounce": {"period": -1}})json"),
     ": /objects/0/animation/bounce/period: ", "must be > 0, got -1"},
    {"AnimationBouncePeriodZero", sphereObject(R"json(, "animation": {"bounce": {"period": 0}})json"),
     ": /objects/0/animation/bounce/period: ", "must be > 0, got 0"},
    {"AnimationBounceSquashOne", sphereObject(R"json(, "animation": {"bounce": {"squash": 1}})json"),
     ": /objects/0/animation/bounce/squash: ", "must be in [0, 1), got 1"},
    {"AnimationBounceHeightNegative", sphereObject(R"json(, "animation": {"bounce": {"height": -2}})json"),
     ": /objects/0/animation/bounce/height: ", "must be >= 0, got -2"},
    {"AnimationSwayVertical", sphereObject(R"json(, "animation": {"sway": {"direction": [0, 1, 0]}})json"),
     ": /objects/0/animation/sway/direction: ", "must be a non-zero horizontal vector"},
    {"AnimationSwayFrequencyNegative", sphereObject(R"json(, "animation": {"sway": {"frequency": -0.5}})json"),
     ": /objects/0/animation/sway/frequency: ", "must be >= 0, got -0.5"},
    {"LightAnimationObjectKind",
     withLight(R"json({"type": "point", "pos": [0, 1, 0], "intensity": [1, 1, 1], "range": 2,
                       "animation": {"bounce": {}}})json"),
     ": /lights/0/animation/bounce: ", "unknown animation 'bounce' (expected one of: orbit, drift)"},
    {"LightOrbitRadiusNegative",
     withLight(R"json({"type": "point", "pos": [0, 1, 0], "intensity": [1, 1, 1], "range": 2,
                       "animation": {"orbit": {"radius": -1}}})json"),
     ": /lights/0/animation/orbit/radius: ", "must be >= 0, got -1"},
    {"LightDriftPeriodZero", withLight(R"json({"type": "point", "pos": [0, 1, 0], "intensity": [1, 1, 1], "range": 2,
                       "animation": {"drift": {"period": [1, 0, 1]}}})json"),
     ": /lights/0/animation/drift/period/1: ", "must be > 0, got 0"},
    {"SetAnimationTypo",
     withSet(R"json({"count": 2, "min": [0, 0, 0], "max": [1, 1, 1], "range": [1, 2], "intensity": [1, 1],
                     "animation": {"orbit": {"phse": 3}}})json"),
     ": /light_sets/0/animation/orbit/phse: ", "(did you mean 'phase'?)"},
    {"LightMarkersRadiusZero", R"json({"light_markers": {"radius": 0}})json",
     ": /light_markers/radius: ", "must be > 0, got 0"},
    {"LightMarkersNoRadius", R"json({"light_markers": {}})json", ": /light_markers: ", "missing required key 'radius'"},
    {"RevolutionAmplitudeTooLarge", withMesh(R"json({"primitive": "revolution", "radius": 0.5, "amplitude": 0.5})json"),
     ": /objects/0/mesh/amplitude: ", "must be less than radius (0.5)"},
    {"RevolutionDynamicWithTime", withMesh(R"json({"primitive": "revolution", "dynamic": true, "time": 1})json"),
     ": /objects/0/mesh/time: ", "applies only to a static surface"},
};

class BadSceneTest : public ::testing::TestWithParam<BadScene> {};

TEST_P(BadSceneTest, ErrorNamesThePosition)
{
    const BadScene& bad = GetParam();
    const std::string message = errorOf(bad.json);
    const std::string prefix = "scene.json" + bad.where;
    EXPECT_EQ(message.substr(0, prefix.size()), prefix) << message;
    EXPECT_NE(message.find(bad.phrase), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.find("json.exception"), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(SceneLoader, BadSceneTest, ::testing::ValuesIn(kBadScenes),
                         [](const ::testing::TestParamInfo<BadScene>& param) { return std::string(param.param.name); });

TEST(SceneLoader, BadSceneTableIsLargeAndNamesAreUnique)
{
    EXPECT_GE(kBadScenes.size(), 40u);
    std::vector<std::string> names;
    for (const BadScene& bad : kBadScenes)
        names.emplace_back(bad.name);
    std::sort(names.begin(), names.end());
    EXPECT_EQ(std::adjacent_find(names.begin(), names.end()), names.end());
}

// Two whole messages, exactly, as a user sees them.
TEST(SceneLoader, NormalScaleDefaultsToOne)
{
    const Scene scene = parse(R"json({"materials": {"flat": {}, "half": {"normal_scale": 0.5}}})json");
    ASSERT_EQ(scene.materials.size(), 2u);
    EXPECT_EQ(scene.materials[0].normalScale, 1.0f);
    EXPECT_EQ(scene.materials[1].normalScale, 0.5f);
}

TEST(SceneLoader, ExactMessages)
{
    EXPECT_EQ(errorOf("{\n  \"lights\": [\n    { \"type\": \"point\", }\n  ]\n}"),
              "scene.json:3:24: syntax error while parsing object key: unexpected '}'; expected string literal");
    EXPECT_EQ(errorOf(R"json({"materials": {"m": {"colour": [1, 0, 0]}}})json"),
              "scene.json: /materials/m/colour: unknown key 'colour' (expected one of: diffuse, specular, shininess, "
              "emissive, diffuse_map, specular_map, normal_map, normal_scale, opacity, opacity_map, base_color, "
              "metallic, roughness, base_color_map, metallic_roughness_map, occlusion_map)");
}

}  // namespace
}  // namespace manylights
