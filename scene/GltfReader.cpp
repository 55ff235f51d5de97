// The glTF file as a whole, its node hierarchy, cameras and punctual lights (scene/GltfReader.h).
#include "scene/GltfReader.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

namespace manylights::detail {

namespace fs = std::filesystem;

namespace {

// Deeper node hierarchies than this are taken for a malformed file (and would risk the stack).
constexpr int kMaxNodeDepth = 1024;

}  // namespace

std::string oneLine(std::string text)
{
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' '))
        text.pop_back();
    std::replace(text.begin(), text.end(), '\n', ' ');
    std::replace(text.begin(), text.end(), '\r', ' ');
    return text;
}

std::string element(const char* array, std::size_t index)
{
    return std::string(array) + "[" + std::to_string(index) + "]";
}

Model GltfReader::read()
{
    checkExtensions();
    meshOf_.assign(gltf_.meshes.size(), std::nullopt);
    materialOf_.assign(gltf_.materials.size(), std::nullopt);
    imagePathOf_.assign(gltf_.images.size(), std::nullopt);
    onPath_.assign(gltf_.nodes.size(), false);
    checkHierarchy();
    for (const int root : rootNodes())
        visit(root, glm::mat4{1.0f}, 0);
    if (model_.instances.empty() && model_.lights.empty())
        fail("its scene has no triangle mesh and no point or spot light");
    if (options_.warnings)
        warnings_.flushInto(*options_.warnings);
    return std::move(model_);
}

void GltfReader::checkExtensions()
{
    const std::set<std::string> supported{"KHR_lights_punctual", "KHR_materials_emissive_strength",
                                          "KHR_texture_transform"};
    for (const std::string& name : gltf_.extensionsRequired)
        if (!supported.contains(name))
            fail("requires the extension " + name + ", which manylights does not read");
    for (const std::string& name : gltf_.extensionsUsed)
        if (!supported.contains(name))
            warnings_.noteFile("extension " + name,
                               "the extension " + name + " is not read; the file is drawn without it");
}

void GltfReader::checkHierarchy() const
{
    std::vector<int> parents(gltf_.nodes.size(), 0);
    for (std::size_t n = 0; n < gltf_.nodes.size(); ++n) {
        for (const int child : gltf_.nodes[n].children) {
            if (child < 0 || static_cast<std::size_t>(child) >= gltf_.nodes.size())
                fail(element("nodes", n) + ": child " + std::to_string(child) + " is not a node (the file has " +
                     std::to_string(gltf_.nodes.size()) + ")");
            if (++parents[static_cast<std::size_t>(child)] > 1)
                fail(element("nodes", static_cast<std::size_t>(child)) + " has more than one parent");
        }
    }
}

std::vector<int> GltfReader::rootNodes() const
{
    if (!gltf_.scenes.empty()) {
        const int chosen = gltf_.defaultScene;
        if (chosen >= static_cast<int>(gltf_.scenes.size()))
            fail("scene " + std::to_string(chosen) + " is not a scene (the file has " +
                 std::to_string(gltf_.scenes.size()) + ")");
        const std::size_t index = chosen < 0 ? 0 : static_cast<std::size_t>(chosen);
        for (const int node : gltf_.scenes[index].nodes)
            if (node < 0 || static_cast<std::size_t>(node) >= gltf_.nodes.size())
                fail(element("scenes", index) + ": node " + std::to_string(node) + " is not a node (the file has " +
                     std::to_string(gltf_.nodes.size()) + ")");
        return gltf_.scenes[index].nodes;
    }
    std::vector<bool> isChild(gltf_.nodes.size(), false);
    for (const tinygltf::Node& node : gltf_.nodes)
        for (const int child : node.children)
            isChild[static_cast<std::size_t>(child)] = true;
    std::vector<int> roots;
    for (std::size_t n = 0; n < gltf_.nodes.size(); ++n)
        if (!isChild[n])
            roots.push_back(static_cast<int>(n));
    return roots;
}

glm::mat4 GltfReader::localMatrix(std::size_t index) const
{
    const tinygltf::Node& node = gltf_.nodes[index];
    const std::string where = element("nodes", index);
    const auto finite = [&](const std::vector<double>& values, std::size_t size, const char* what) {
        if (values.empty())
            return false;
        if (values.size() != size)
            fail(where + ": " + what + " needs " + std::to_string(size) + " numbers, has " +
                 std::to_string(values.size()));
        for (const double v : values)
            if (!std::isfinite(static_cast<float>(v)))
                fail(where + ": " + what + " has a non-finite number");
        return true;
    };
    if (finite(node.matrix, 16, "matrix")) {
        glm::mat4 m;
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                m[c][r] = static_cast<float>(node.matrix[static_cast<std::size_t>(c * 4 + r)]);
        if (m[0][3] != 0.0f || m[1][3] != 0.0f || m[2][3] != 0.0f || m[3][3] != 1.0f)
            fail(where + ": matrix is not affine (its last row must be 0, 0, 0, 1)");
        return m;
    }
    glm::mat4 m{1.0f};
    if (finite(node.translation, 3, "translation"))
        m = glm::translate(m, glm::vec3(node.translation[0], node.translation[1], node.translation[2]));
    if (finite(node.rotation, 4, "rotation")) {
        // glTF stores x, y, z, w; glm::quat's constructor takes w first.
        glm::quat q(static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]),
                    static_cast<float>(node.rotation[1]), static_cast<float>(node.rotation[2]));
        const float length = glm::length(q);
        if (!(length > 0.0f))
            fail(where + ": rotation is the zero quaternion");
        m *= glm::mat4_cast(q / length);
    }
    if (finite(node.scale, 3, "scale"))
        m = glm::scale(m, glm::vec3(node.scale[0], node.scale[1], node.scale[2]));
    return m;
}

void GltfReader::visit(int nodeIndex, const glm::mat4& parent, int depth)
{
    const auto index = static_cast<std::size_t>(nodeIndex);
    if (depth > kMaxNodeDepth)
        fail(element("nodes", index) + ": the node hierarchy is deeper than " + std::to_string(kMaxNodeDepth));
    if (onPath_[index])
        fail(element("nodes", index) + " is its own ancestor (the node hierarchy has a cycle)");
    const tinygltf::Node& node = gltf_.nodes[index];
    const glm::mat4 world = parent * localMatrix(index);
    const std::string name = node.name.empty() ? element("nodes", index) : node.name;
    if (node.mesh >= 0) {
        if (static_cast<std::size_t>(node.mesh) >= gltf_.meshes.size())
            fail(element("nodes", index) + ": mesh " + std::to_string(node.mesh) + " is not a mesh (the file has " +
                 std::to_string(gltf_.meshes.size()) + ")");
        const float determinant = glm::determinant(glm::mat3(world));
        // A zero scale hides a node (and would make its normals undefined): not drawn.
        if (determinant != 0.0f && std::isfinite(determinant)) {
            if (const auto mesh = meshFor(static_cast<std::size_t>(node.mesh)))
                model_.instances.push_back({name, *mesh, world});
        }
    }
    if (const auto light = punctualLight(node))
        addLight(*light, world, index);
    if (node.camera >= 0)
        addCamera(node.camera, world, name, index);
    onPath_[index] = true;
    for (const int child : node.children)
        visit(child, world, depth + 1);
    onPath_[index] = false;
}

void GltfReader::addCamera(int cameraIndex, const glm::mat4& world, const std::string& name, std::size_t nodeIndex)
{
    if (static_cast<std::size_t>(cameraIndex) >= gltf_.cameras.size())
        fail(element("nodes", nodeIndex) + ": camera " + std::to_string(cameraIndex) +
             " is not a camera (the file has " + std::to_string(gltf_.cameras.size()) + ")");
    const tinygltf::Camera& source = gltf_.cameras[static_cast<std::size_t>(cameraIndex)];
    const std::string where = element("cameras", static_cast<std::size_t>(cameraIndex));
    if (source.type != "perspective") {
        warnings_.noteFile("camera " + source.type,
                           where + ": type " + source.type + " has no counterpart in the scene's camera; passed over");
        return;
    }
    const tinygltf::PerspectiveCamera& perspective = source.perspective;
    const double fovDegrees = glm::degrees(perspective.yfov);
    if (!(fovDegrees > 0.0 && fovDegrees < 180.0))
        fail(where + ": yfov must be in (0, pi), got " + std::to_string(perspective.yfov));
    if (!(perspective.znear > 0.0) || !std::isfinite(perspective.znear))
        fail(where + ": znear must be a positive finite number");
    Camera camera;
    camera.fovYDegrees = static_cast<float>(fovDegrees);
    camera.nearPlane = static_cast<float>(perspective.znear);
    camera.farPlane = perspective.zfar > perspective.znear && std::isfinite(perspective.zfar)
                          ? static_cast<float>(perspective.zfar)
                          : std::max(camera.farPlane, 1000.0f * camera.nearPlane);
    camera.eye = glm::vec3(world * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    const glm::vec3 forward = glm::vec3(world * glm::vec4(0.0f, 0.0f, -1.0f, 0.0f));
    camera.up = glm::vec3(world * glm::vec4(0.0f, 1.0f, 0.0f, 0.0f));
    if (!(glm::length(forward) > 0.0f) || !(glm::length(camera.up) > 0.0f))
        fail(element("nodes", nodeIndex) + ": the camera's node has a singular transform");
    camera.lookAt = camera.eye + glm::normalize(forward);
    model_.cameras.push_back({name, camera});
}

std::optional<std::size_t> GltfReader::punctualLight(const tinygltf::Node& node) const
{
    const auto found = node.extensions.find("KHR_lights_punctual");
    if (found == node.extensions.end() || !found->second.IsObject() || !found->second.Has("light"))
        return std::nullopt;
    const tinygltf::Value& value = found->second.Get("light");
    if (!value.IsInt() || value.GetNumberAsInt() < 0 ||
        static_cast<std::size_t>(value.GetNumberAsInt()) >= gltf_.lights.size())
        fail("KHR_lights_punctual: a node names light " +
             (value.IsNumber() ? std::to_string(value.GetNumberAsInt()) : std::string("(not an integer)")) +
             ", the file has " + std::to_string(gltf_.lights.size()));
    return static_cast<std::size_t>(value.GetNumberAsInt());
}

void GltfReader::addLight(std::size_t lightIndex, const glm::mat4& world, std::size_t nodeIndex)
{
    const tinygltf::Light& source = gltf_.lights[lightIndex];
    const std::string where = "KHR_lights_punctual.lights[" + std::to_string(lightIndex) + "]";
    // Directional lights have no place among the local lights; the scene file's
    // `directional` is the one directional light.
    if (source.type == "directional")
        return;
    if (source.type != "point" && source.type != "spot")
        fail(where + ": unknown type '" + source.type + "' (expected point, spot or directional)");
    glm::vec3 colour{1.0f};
    if (!source.color.empty()) {
        if (source.color.size() != 3)
            fail(where + ": color needs 3 numbers, has " + std::to_string(source.color.size()));
        colour = glm::vec3(source.color[0], source.color[1], source.color[2]);
    }
    // Candela divided by π (docs/lighting.md, "Units"): with the lighting's k = π, a pixel is
    // then the physical radiance, in nits, of the surfaces the light reaches.
    const glm::vec3 intensity = colour * static_cast<float>(source.intensity / std::numbers::pi);
    if (!std::isfinite(intensity.x + intensity.y + intensity.z) || glm::any(glm::lessThan(intensity, glm::vec3{0.0f})))
        fail(where + ": color and intensity must be finite and not negative");
    const float maxIntensity = std::max({intensity.r, intensity.g, intensity.b});
    if (maxIntensity == 0.0f)
        return;  // lights nothing
    Light light;
    light.name = gltf_.nodes[nodeIndex].name.empty() ? element("nodes", nodeIndex) : gltf_.nodes[nodeIndex].name;
    light.intensity = intensity;
    light.falloff = Falloff::Range;
    if (source.range < 0.0 || !std::isfinite(source.range))
        fail(where + ": range must be a positive finite number");
    if (source.range > 0.0) {
        light.range = static_cast<float>(source.range);
        if (!std::isfinite(light.range) || light.range <= 0.0f)
            fail(where + ": range must be a positive finite number");
    } else {
        // No range: inverse-square light cut where it falls to the attenuation threshold,
        // I/r² = t.
        light.range = std::sqrt(maxIntensity / options_.attenuationThreshold);
        if (!std::isfinite(light.range))
            fail(where + ": intensity too large for a light without range");
    }
    light.position = glm::vec3(world[3]);
    if (source.type == "spot") {
        light.type = LightType::Spot;
        const glm::vec3 axis = glm::mat3(world) * glm::vec3{0.0f, 0.0f, -1.0f};
        const float axisLength = glm::length(axis);
        if (!(axisLength > 0.0f) || !std::isfinite(axisLength))
            return;  // a zero-scaled node: the spot has no direction and is hidden like a mesh
        light.direction = axis / axisLength;
        const double inner = source.spot.innerConeAngle;
        const double outer = source.spot.outerConeAngle;
        if (!(outer > 0.0 && outer <= std::numbers::pi / 2) || !(inner >= 0.0 && inner < outer))
            fail(where + ": spot cone angles need 0 <= innerConeAngle < outerConeAngle <= pi/2");
        light.cutoffDegrees = static_cast<float>(outer * 180.0 / std::numbers::pi);
        // glTF fades linearly in cos θ from the outer to the inner cone; (cos θ)^e with e chosen
        // so that it is 1/2 where glTF's fade is 1/2 (cos θ midway between the two cosines).
        const double middle = 0.5 * (std::cos(inner) + std::cos(outer));
        light.exponent =
            middle > 0.0 && middle < 1.0 ? static_cast<float>(std::min(std::log(0.5) / std::log(middle), 128.0)) : 0.0f;
    }
    model_.lights.push_back(light);
}

}  // namespace manylights::detail
