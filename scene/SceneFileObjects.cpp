// The scene file's objects, meshes and transforms (scene/SceneFileLoader.h has the index).
#include "scene/SceneFileLoader.h"

#include <algorithm>
#include <cmath>

#include "scene/GltfLoader.h"
#include "scene/MaterialModels.h"
#include "scene/Meshes.h"
#include "scene/ObjLoader.h"
#include "scene/Tangents.h"
#include "scene/Transform.h"

namespace manylights::scene_file {

using namespace scene_json;  // the wording of messages (scene/JsonText.h)

void Loader::readObject(const Node& node, std::size_t index)
{
    expectKeys(node, {"name", "mesh", "material", "transform", "animation"});
    Object object;
    if (const auto name = member(node, "name"))
        object.name = string(*name);
    else
        object.name = "objects[" + std::to_string(index) + "]";
    const Node meshNode = required(node, "mesh");
    const LoadedModel* model = nullptr;
    dynamicRevolution_.reset();
    if (meshNode.json->is_string())
        model = &modelFile(meshNode);
    else
        object.mesh = readMesh(meshNode);
    object.revolution = dynamicRevolution_;
    object.material = objectMaterial(node);
    object.materialOverridesMesh = member(node, "material").has_value();
    if (const auto transform = member(node, "transform"))
        object.transform = readTransform(*transform);
    if (const auto animation = member(node, "animation"))
        object.animation = readObjectAnimation(*animation);
    if (!model) {
        scene_.objects.push_back(object);
        return;
    }
    if (!model->namesInstances) {
        object.mesh = model->instances.front().mesh;
        scene_.objects.push_back(object);
        return;
    }
    if (scene_.objects.size() + model->instances.size() > kMaxObjects)
        fail(meshNode, "too many objects (at most " + std::to_string(kMaxObjects) + ")");
    for (const ModelInstance& instance : model->instances) {
        Object part = object;
        part.name = object.name + "/" + instance.name;
        part.mesh = instance.mesh;
        part.transform = object.transform * instance.transform;
        scene_.objects.push_back(std::move(part));
    }
    if (scene_.lights.size() + model->lights.size() > kMaxLights)
        fail(meshNode, "too many lights (at most " + std::to_string(kMaxLights) + ")");
    for (Light light : model->lights) {
        light.name = object.name + "/" + light.name;
        light.position = glm::vec3(object.transform * glm::vec4(light.position, 1.0f));
        light.direction = glm::normalize(glm::mat3(object.transform) * light.direction);
        scene_.lights.push_back(std::move(light));
    }
    for (NamedCamera camera : model->cameras) {
        camera.name = object.name + "/" + camera.name;
        Camera& c = camera.camera;
        const glm::vec3 eye = glm::vec3(object.transform * glm::vec4(c.eye, 1.0f));
        c.lookAt = eye + glm::normalize(glm::mat3(object.transform) * (c.lookAt - c.eye));
        c.up = glm::normalize(glm::mat3(object.transform) * c.up);
        c.eye = eye;
        scene_.cameras.push_back(std::move(camera));
    }
}

ObjectAnimation Loader::readObjectAnimation(const Node& node) const
{
    const auto [kind, settings] = animationKind(node, {"spin", "sway", "bounce"});
    if (kind == "spin") {
        expectKeys(settings, {"axis", "speed", "phase", "pivot"});
        SpinAnimation spin;
        if (const auto axis = member(settings, "axis"))
            spin.axis = direction(*axis);
        spin.degreesPerSecond = optionalNumber(settings, "speed", spin.degreesPerSecond, &Reader::number);
        spin.phaseDegrees = optionalNumber(settings, "phase", spin.phaseDegrees, &Reader::number);
        if (const auto pivot = member(settings, "pivot"))
            spin.pivot = vec3(*pivot);
        return spin;
    }
    if (kind == "sway") {
        expectKeys(settings, {"direction", "amplitude", "frequency", "phase", "base"});
        SwayAnimation sway;
        if (const auto directionNode = member(settings, "direction")) {
            sway.direction = vec3(*directionNode);
            if (sway.direction.y != 0.0f || (sway.direction.x == 0.0f && sway.direction.z == 0.0f))
                fail(*directionNode, "must be a non-zero horizontal vector [x, 0, z]");
        }
        sway.amplitude = optionalNumber(settings, "amplitude", sway.amplitude, &Reader::nonNegative);
        sway.frequency = optionalNumber(settings, "frequency", sway.frequency, &Reader::nonNegative);
        sway.phaseDegrees = optionalNumber(settings, "phase", sway.phaseDegrees, &Reader::number);
        sway.base = optionalNumber(settings, "base", sway.base, &Reader::number);
        return sway;
    }
    expectKeys(settings, {"height", "period", "phase", "squash", "base"});
    BounceAnimation bounce;
    bounce.height = optionalNumber(settings, "height", bounce.height, &Reader::nonNegative);
    bounce.period = optionalNumber(settings, "period", bounce.period, &Reader::positive);
    bounce.phase = optionalNumber(settings, "phase", bounce.phase, &Reader::fraction);
    bounce.squash = optionalNumber(settings, "squash", bounce.squash, &Reader::fraction);
    bounce.base = optionalNumber(settings, "base", bounce.base, &Reader::number);
    return bounce;
}

std::size_t Loader::addMesh(const std::string& key, Mesh mesh)
{
    if (mesh.name.empty())
        mesh.name = key;
    generateTangentsIfMissing(mesh);
    meshCache_.emplace(key, scene_.meshes.size());
    scene_.meshes.push_back(std::move(mesh));
    return scene_.meshes.size() - 1;
}

std::size_t Loader::readMesh(const Node& node)
{
    if (node.json->is_object())
        return primitive(node);
    fail(node, "expected a mesh file path or a primitive object, got " + describeType(*node.json));
}

const Loader::LoadedModel& Loader::modelFile(const Node& node)
{
    const fs::path path = resolve(node);
    const std::string extension = toLower(path.extension().string());
    const bool gltf = extension == ".gltf" || extension == ".glb";
    if (extension != ".obj" && !gltf)
        fail(node, (extension.empty() ? std::string("mesh file has no extension")
                                      : "unsupported mesh file type " + quote(extension)) +
                       " (expected .obj, .gltf or .glb)");
    expectRegularFile(node, path);
    // One copy per file, however many objects use it, so a scene of many bunnies loads
    // (and uploads) one bunny.
    std::error_code error;
    fs::path canonical = fs::weakly_canonical(path, error);
    if (error)
        canonical = path;
    const std::string key = canonical.string();
    if (const auto cached = modelCache_.find(key); cached != modelCache_.end())
        return cached->second;
    Model model;
    // Under --strict the first forgiven problem throws, and is reported as any error is.
    Warnings forgiven(options_.strict);
    try {
        if (gltf) {
            GltfOptions options;
            options.attenuationThreshold = scene_.attenuationThreshold;
            options.warnings = &forgiven;
            model = loadGltfFile(path, options);
        } else {
            model = loadObjModelFile(path, forgiven);
        }
    } catch (const Error& e) {
        fail(node, e.what());
    }
    for (const std::string& message : forgiven.messages())
        scene_.warnings.push_back(located(node, message));
    const std::size_t materialOffset = scene_.materials.size();
    const std::size_t meshOffset = scene_.meshes.size();
    for (Material& material : model.materials)
        scene_.materials.push_back(modelMaterialsAsBlinnPhong_ ? blinnPhongMapping(material) : std::move(material));
    for (Mesh& mesh : model.meshes) {
        for (SubMesh& range : mesh.subMeshes)
            if (range.material)
                *range.material += materialOffset;
        if (mesh.name.empty())
            mesh.name = path.string();
        scene_.meshes.push_back(std::move(mesh));
    }
    for (EncodedImage& image : model.images)
        scene_.encodedImages.push_back(std::move(image));
    LoadedModel loaded;
    loaded.namesInstances = gltf;
    loaded.lights = std::move(model.lights);
    loaded.cameras = std::move(model.cameras);
    for (ModelInstance instance : model.instances) {
        instance.mesh += meshOffset;
        loaded.instances.push_back(std::move(instance));
    }
    return modelCache_.emplace(key, std::move(loaded)).first->second;
}

std::size_t Loader::primitive(const Node& node)
{
    const Node kindNode = required(node, "primitive");
    const std::string kind = string(kindNode);
    // Parameters go into the cache key in full float precision: only truly identical
    // primitives share a mesh.
    auto cached = [&](const std::string& key, auto make) {
        if (const auto found = meshCache_.find(key); found != meshCache_.end())
            return found->second;
        return addMesh(key, make());
    };
    if (kind == "plane") {
        expectKeys(node, {"primitive", "size"});
        const Node size = required(node, "size");
        expectNumberArray(size, 2);
        const float x = positive(element(size, 0));
        const float z = positive(element(size, 1));
        return cached("plane(size=[" + formatFloat(x) + ", " + formatFloat(z) + "])", [&] { return makePlane(x, z); });
    }
    if (kind == "box") {
        expectKeys(node, {"primitive", "size"});
        const glm::vec3 size = vec3(required(node, "size"), &Reader::positive);
        return cached("box(size=[" + formatFloat(size.x) + ", " + formatFloat(size.y) + ", " + formatFloat(size.z) +
                          "])",
                      [&] { return makeBox(size); });
    }
    if (kind == "sphere") {
        expectKeys(node, {"primitive", "radius"});
        const float radius = positive(required(node, "radius"));
        return cached("sphere(radius=" + formatFloat(radius) + ")", [&] { return makeSphere(radius); });
    }
    if (kind == "cone" || kind == "cylinder") {
        expectKeys(node, {"primitive", "radius", "height"});
        const float radius = positive(required(node, "radius"));
        const float height = positive(required(node, "height"));
        const std::string key = kind + "(radius=" + formatFloat(radius) + ", height=" + formatFloat(height) + ")";
        if (kind == "cone")
            return cached(key, [&] { return makeCone(radius, height); });
        return cached(key, [&] { return makeCylinder(radius, height); });
    }
    if (kind == "torus") {
        expectKeys(node, {"primitive", "radius", "tube"});
        const float radius = positive(required(node, "radius"));
        const float tube = positive(required(node, "tube"));
        return cached("torus(radius=" + formatFloat(radius) + ", tube=" + formatFloat(tube) + ")",
                      [&] { return makeTorus(radius, tube); });
    }
    if (kind == "revolution")
        return revolution(node);
    const std::vector<std::string> kinds{"plane", "box", "sphere", "cone", "cylinder", "torus", "revolution"};
    fail(kindNode, "unknown primitive " + quote(kind) + nameHint(kind, kinds));
}

std::size_t Loader::revolution(const Node& node)
{
    expectKeys(node, {"primitive", "radius", "height", "amplitude", "waves", "speed", "time", "dynamic"});
    RevolutionProfile profile;
    profile.radius = optionalNumber(node, "radius", profile.radius, &Reader::positive);
    profile.height = optionalNumber(node, "height", profile.height, &Reader::positive);
    profile.amplitude = optionalNumber(node, "amplitude", profile.amplitude, &Reader::nonNegative);
    profile.waves = optionalNumber(node, "waves", profile.waves, &Reader::nonNegative);
    profile.speed = optionalNumber(node, "speed", profile.speed, &Reader::number);
    if (profile.amplitude >= profile.radius)
        fail(*member(node, "amplitude"),
             "must be less than radius (" + formatFloat(profile.radius) + ") or the surface pinches through its axis");
    const auto dynamic = member(node, "dynamic");
    const bool isDynamic = dynamic && boolean(*dynamic);
    const auto time = member(node, "time");
    if (time && isDynamic)
        fail(*time, "applies only to a static surface (this one has \"dynamic\": true)");
    const float frozenAt = time ? number(*time) : 0.0f;
    if (isDynamic)
        dynamicRevolution_ = profile;
    // Not cached: two surfaces with the same profile are rare, and the key would be long.
    Mesh mesh = makeRevolutionMesh(profile, isDynamic ? 0.0 : frozenAt);
    mesh.name = isDynamic ? "revolution(dynamic)" : "revolution";
    scene_.meshes.push_back(std::move(mesh));
    return scene_.meshes.size() - 1;
}

glm::mat4 Loader::readTransform(const Node& node) const
{
    expectKeys(node, {"translate", "rotate", "scale", "matrix"});
    if (const auto matrix = member(node, "matrix")) {
        if (member(node, "translate") || member(node, "rotate") || member(node, "scale"))
            fail(node, "give either 'matrix' or 'translate'/'rotate'/'scale', not both");
        return readMatrix(*matrix);
    }
    glm::vec3 translate(0.0f);
    glm::vec3 rotate(0.0f);
    glm::vec3 scale(1.0f);
    if (const auto t = member(node, "translate"))
        translate = vec3(*t);
    if (const auto r = member(node, "rotate"))
        rotate = vec3(*r);
    if (const auto s = member(node, "scale")) {
        if (s->json->is_number())
            scale = glm::vec3(nonZero(*s));
        else if (s->json->is_array())
            scale = vec3(*s, &Reader::nonZero);
        else
            fail(*s, "expected a number or an array of 3 numbers, got " + describeType(*s->json));
    }
    return composeTransform(translate, rotate, scale);
}

glm::mat4 Loader::readMatrix(const Node& node) const
{
    expectNumberArray(node, 16);
    glm::mat4 m;
    for (int column = 0; column < 4; ++column)
        for (int row = 0; row < 4; ++row)
            m[column][row] = number(element(node, static_cast<std::size_t>(column * 4 + row)));
    // Normals, bounds and light culling all assume an affine transform. A translation in
    // elements 3, 7, 11 is also the usual sign of a matrix written row-major.
    if (m[0][3] != 0.0f || m[1][3] != 0.0f || m[2][3] != 0.0f || m[3][3] != 1.0f)
        fail(node, "must be affine: elements 3, 7, 11, 15 (the bottom row, column-major) must be 0, 0, 0, 1, got " +
                       formatFloat(m[0][3]) + ", " + formatFloat(m[1][3]) + ", " + formatFloat(m[2][3]) + ", " +
                       formatFloat(m[3][3]) + " (is it row-major?)");
    const float determinant = glm::determinant(glm::mat3(m));
    if (determinant == 0.0f || !std::isfinite(determinant))
        fail(node, "is singular (the determinant of its 3x3 part is " + formatFloat(determinant) + ")");
    return m;
}

}  // namespace manylights::scene_file
