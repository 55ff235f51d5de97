// The scene file's reader (docs/scene-format.md): parseScene and loadSceneFile, and the
// file's top level with its small sections (camera, directional, display, ssao, environment).
// The other sections have files of their own; scene/SceneFileLoader.h has the index.
#include "scene/SceneLoader.h"

#include <algorithm>
#include <cctype>
#include <string>

#include "core/InputFile.h"
#include "scene/SceneFileLoader.h"
#include "scene/ShadowSelection.h"

namespace manylights {

namespace scene_file {

using namespace scene_json;  // the JSON text and the wording of messages (scene/JsonText.h)

Scene Loader::load(const Json& root)
{
    const Node top{&root, ""};
    if (!root.is_object())
        fail(top, "the top level must be a JSON object, got " + describeType(root));
    expectKeys(top, {"camera", "background", "ambient", "directional", "attenuation_threshold", "lights", "light_sets",
                     "materials", "objects", "light_markers", "ssao", "display", "model_materials", "environment",
                     "shadow_lights"});
    // Before the objects, which load the model files it applies to.
    if (const auto node = member(top, "model_materials"))
        modelMaterialsAsBlinnPhong_ = oneOf(*node, {"metallic-roughness", "blinn-phong"}) == "blinn-phong";
    if (const auto node = member(top, "camera"))
        readCamera(*node);
    if (const auto node = member(top, "background"))
        scene_.background = colour(*node);
    if (const auto node = member(top, "ambient"))
        scene_.ambient = colour(*node);
    if (const auto node = member(top, "directional"))
        scene_.directional = readDirectional(*node);
    if (const auto node = member(top, "shadow_lights"))
        scene_.shadowLights = readShadowLights(*node);
    if (const auto node = member(top, "ssao"))
        scene_.ssao = readAmbientOcclusion(*node);
    if (const auto node = member(top, "display"))
        scene_.display = readDisplay(*node);
    if (const auto node = member(top, "environment"))
        scene_.environment = readEnvironment(*node);
    if (const auto node = member(top, "attenuation_threshold"))
        scene_.attenuationThreshold = positive(*node);
    if (const auto node = member(top, "lights")) {
        expectArray(*node, kMaxLights, "lights");
        for (std::size_t i = 0; i < node->json->size(); ++i)
            scene_.lights.push_back(readLight(element(*node, i), i));
    }
    if (const auto node = member(top, "light_sets"))
        readLightSets(*node);
    if (const auto node = member(top, "materials"))
        readMaterials(*node);
    if (const auto node = member(top, "objects")) {
        expectArray(*node, kMaxObjects, "objects");
        for (std::size_t i = 0; i < node->json->size(); ++i)
            readObject(element(*node, i), i);
    }
    if (const auto node = member(top, "light_markers")) {
        expectKeys(*node, {"radius"});
        scene_.lightMarkerRadius = positive(required(*node, "radius"));
    }
    return std::move(scene_);
}

void Loader::readCamera(const Node& node)
{
    expectKeys(node, {"eye", "look_at", "up", "fov_y", "near", "far"});
    Camera& camera = scene_.camera;
    const auto eye = member(node, "eye");
    const auto lookAt = member(node, "look_at");
    const auto up = member(node, "up");
    if (eye)
        camera.eye = vec3(*eye);
    if (lookAt)
        camera.lookAt = vec3(*lookAt);
    if (up)
        camera.up = direction(*up);
    if (const auto fov = member(node, "fov_y")) {
        camera.fovYDegrees = number(*fov);
        if (!(camera.fovYDegrees > 0.0f && camera.fovYDegrees < 180.0f))
            fail(*fov, "must be in (0, 180), got " + describeValue(*fov->json));
    }
    if (const auto nearNode = member(node, "near"))
        camera.nearPlane = positive(*nearNode);
    if (const auto farNode = member(node, "far")) {
        camera.farPlane = number(*farNode);
        if (!(camera.farPlane > camera.nearPlane))
            fail(*farNode, "must be greater than near (" + formatFloat(camera.nearPlane) + "), got " +
                               describeValue(*farNode->json));
    } else if (!(camera.farPlane > camera.nearPlane)) {
        fail(*member(node, "near"), "must be less than far (" + formatFloat(camera.farPlane) + ")");
    }

    switch (const CameraProblem problem = cameraProblem(camera); problem) {
    case CameraProblem::None: break;
    case CameraProblem::LookAtIsEye:
    case CameraProblem::DistanceOverflows: fail(lookAt ? *lookAt : (eye ? *eye : node), describe(problem));
    case CameraProblem::UpAlongView: fail(up ? *up : node, describe(problem));
    }
}

DirectionalLight Loader::readDirectional(const Node& node) const
{
    expectKeys(node, {"direction", "intensity", "shadows"});
    DirectionalLight light;
    light.direction = direction(required(node, "direction"));
    light.intensity = colour(required(node, "intensity"));
    if (const auto shadows = member(node, "shadows"))
        light.shadows = boolean(*shadows);
    return light;
}

// "shadow_lights": a whole number of lights, or "all" (kAllShadowLights): --shadow-lights's values.
int Loader::readShadowLights(const Node& node) const
{
    const std::string expected = "expected a whole number of lights or " + quote("all") + ", got ";
    if (node.json->is_string()) {
        if (const std::string text = string(node); text != "all")
            fail(node, expected + quote(text));
        return kAllShadowLights;
    }
    if (!node.json->is_number())
        fail(node, expected + describeType(*node.json));
    return static_cast<int>(integer(node, 0, kAllShadowLights));
}

DisplaySettings Loader::readDisplay(const Node& node) const
{
    expectKeys(node, {"exposure", "tonemap", "srgb", "aa"});
    DisplaySettings display;
    if (const auto exposure = member(node, "exposure")) {
        display.exposure = number(*exposure);
        if (std::abs(display.exposure) > kMaxExposureStops)
            fail(*exposure, "must be in [-32, 32] stops, got " + describeValue(*exposure->json));
    }
    if (const auto tonemap = member(node, "tonemap"))
        display.toneCurve = *parseToneCurve(oneOf(*tonemap, toneCurveNames()));
    if (const auto srgb = member(node, "srgb"))
        display.srgb = boolean(*srgb);
    if (const auto aa = member(node, "aa"))
        display.antialiasing = *parseAntialiasing(oneOf(*aa, antialiasingNames()));
    return display;
}

AmbientOcclusion Loader::readAmbientOcclusion(const Node& node) const
{
    expectKeys(node, {"enabled", "radius", "strength"});
    AmbientOcclusion ao;
    ao.enabled = true;  // writing the block asks for it; "enabled": false keeps the settings
    if (const auto enabled = member(node, "enabled"))
        ao.enabled = boolean(*enabled);
    if (const auto radius = member(node, "radius"))
        ao.radius = positive(*radius);
    if (const auto strength = member(node, "strength"))
        ao.strength = nonNegative(*strength);
    return ao;
}

Environment Loader::readEnvironment(const Node& node) const
{
    expectKeys(node, {"map", "intensity", "rotation", "background"});
    Environment environment;
    const Node map = required(node, "map");
    environment.map = string(map);
    if (isBuiltinEnvironment(environment.map)) {
        // One built-in so far; the prefix is reserved for more.
        oneOf(map, {std::string(kStudioEnvironment)});
    } else {
        const fs::path path = resolve(map);
        std::string extension = path.extension().string();
        std::transform(extension.begin(), extension.end(), extension.begin(),
                       [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        if (extension != ".hdr" && extension != ".exr")
            fail(map, "must be a .hdr or .exr file or " + std::string(kStudioEnvironment) + ", got " +
                          describeValue(*map.json));
        expectRegularFile(map, path);
        environment.map = path.string();
    }
    // number() refuses what overflows a float, so the intensity is finite.
    if (const auto intensity = member(node, "intensity"))
        environment.look.intensity = nonNegative(*intensity);
    if (const auto rotation = member(node, "rotation"))
        environment.look.rotationDegrees = number(*rotation);
    if (const auto background = member(node, "background"))
        environment.look.background = boolean(*background);
    return environment;
}

}  // namespace scene_file

Scene parseScene(const std::string& jsonText, const std::string& displayName,
                 const std::filesystem::path& baseDirectory, const SceneLoadOptions& options)
{
    const scene_json::Json root = scene_json::parseJson(jsonText, displayName);
    Scene scene = scene_file::Loader(displayName, baseDirectory, options).load(root);
    scene.source = displayName;
    return scene;
}

Scene loadSceneFile(const std::filesystem::path& path, const SceneLoadOptions& options)
{
    const std::string displayName = path.string();
    const std::string text = readInputFile(path, "scene file");
    Scene scene = parseScene(text, displayName, path.parent_path(), options);
    scene.source = displayName;
    return scene;
}

}  // namespace manylights
