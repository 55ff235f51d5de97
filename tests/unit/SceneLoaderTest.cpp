// The scene file (docs/scene-format.md): the example scene read field by field, defaults, sharing of
// meshes and materials, transforms, animations and the files an error names (the bad scenes'
// messages: BadSceneTest.cpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <map>
#include <unistd.h>

#include "SceneFileTestSupport.h"
#include "core/Error.h"
#include "scene/Revolution.h"
#include "scene/SceneLoader.h"
#include "scene/ShadowSelection.h"
#include "scene/Transform.h"

namespace manylights {
namespace {

namespace fs = std::filesystem;
using test::errorOf;
using test::kSceneDir;
using test::parse;
using test::resolved;

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

// Issue 47: "shadow_lights" (none unless given, so --shadow-lights or 0 decides), a whole number
// or "all"; "casts_shadows" on lights and light sets, true unless given.
TEST(SceneLoader, ShadowLightsAndCastsShadows)
{
    EXPECT_FALSE(parse("{}").shadowLights.has_value());
    EXPECT_EQ(parse(R"json({"shadow_lights": 0})json").shadowLights, std::optional<int>(0));
    EXPECT_EQ(parse(R"json({"shadow_lights": 4096})json").shadowLights, std::optional<int>(4096));
    // Above the old budget of 256: the pool has none.
    EXPECT_EQ(parse(R"json({"shadow_lights": 1e6})json").shadowLights, std::optional<int>(1000000));
    EXPECT_EQ(parse(R"json({"shadow_lights": "all"})json").shadowLights, std::optional<int>(kAllShadowLights));

    const Scene scene = parse(R"json({
        "lights": [
            { "type": "point", "pos": [0, 0, 0], "intensity": [1, 1, 1], "range": 1 },
            { "type": "point", "pos": [0, 0, 0], "intensity": [1, 1, 1], "range": 1, "casts_shadows": false },
            { "type": "spot", "pos": [0, 0, 0], "intensity": [1, 1, 1], "direction": [0, -1, 0], "cutoff": 30,
              "range": 1, "casts_shadows": true }
        ],
        "light_sets": [
            { "count": 2, "min": [0, 0, 0], "max": [1, 1, 1], "range": [1, 2], "intensity": [0, 1] },
            { "count": 2, "min": [0, 0, 0], "max": [1, 1, 1], "range": [1, 2], "intensity": [0, 1],
              "casts_shadows": false }
        ] })json");
    ASSERT_EQ(scene.lights.size(), 3u);
    EXPECT_TRUE(scene.lights[0].castsShadows);
    EXPECT_FALSE(scene.lights[1].castsShadows);
    EXPECT_TRUE(scene.lights[2].castsShadows);
    ASSERT_EQ(scene.lightSets.size(), 2u);
    EXPECT_TRUE(scene.lightSets[0].castsShadows);
    EXPECT_FALSE(scene.lightSets[1].castsShadows);
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

TEST(SceneLoader, NormalScaleDefaultsToOne)
{
    const Scene scene = parse(R"json({"materials": {"flat": {}, "half": {"normal_scale": 0.5}}})json");
    ASSERT_EQ(scene.materials.size(), 2u);
    EXPECT_EQ(scene.materials[0].normalScale, 1.0f);
    EXPECT_EQ(scene.materials[1].normalScale, 0.5f);
}

TEST(SceneLoader, DisplayBlockNamesEveryToneCurve)
{
    // Every --tonemap name is also the display block's (issue 48 added pbr-neutral to both).
    ASSERT_NE(std::find(toneCurveNames().begin(), toneCurveNames().end(), "pbr-neutral"), toneCurveNames().end());
    for (const std::string& name : toneCurveNames()) {
        const Scene scene = parse(R"({"display": {"tonemap": ")" + name + R"("}})");
        EXPECT_EQ(toneCurveName(scene.display.toneCurve), name);
    }
    EXPECT_EQ(parse(R"({"display": {"tonemap": "pbr-neutral"}})").display.toneCurve, ToneCurve::PbrNeutral);
}

}  // namespace
}  // namespace manylights
