// The glTF 2.0 loader (.gltf and .glb, docs/scene-format.md): tinygltf parses the file, and
// this file checks every accessor, buffer view and image against its buffer before reading it,
// then turns meshes, materials (metallic-roughness to Blinn-Phong) and the node hierarchy into
// a Model. A malformed file is an Error naming the file and the JSON path.
#include "scene/GltfLoader.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <set>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

// tinygltf configuration (the one translation unit that holds its implementation):
// - no stb_image / stb_image_write: images stay encoded; the render layer decodes them. Our
//   image callback keeps data: URI bytes and leaves buffer-view images to be read (after the
//   buffer view is checked) by this file.
// - no external images: an image URI is only a path, checked to exist here.
// - JSON: Debian's tiny_gltf.h includes <nlohmann/json.hpp>, the same nlohmann json the scene
//   loader uses.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

#include "core/Error.h"
#include "core/InputFile.h"
#include "scene/GltfFieldChecks.h"
#include "scene/Meshes.h"

namespace manylights {

namespace fs = std::filesystem;

namespace {

// Deeper node hierarchies than this are taken for a malformed file (and would risk the stack).
constexpr int kMaxNodeDepth = 1024;

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

// tinygltf image callback: keeps the still-encoded bytes of data: URI images. Buffer-view
// images are left alone here: tinygltf hands them over without checking that the view lies
// inside its buffer, so GltfReader reads them itself after that check.
bool keepEncodedImage(tinygltf::Image* image, const int /*index*/, std::string* /*error*/, std::string* /*warning*/,
                      int /*width*/, int /*height*/, const unsigned char* bytes, int size, void* /*user*/)
{
    if (image->bufferView < 0 && bytes != nullptr && size > 0)
        image->image.assign(bytes, bytes + size);
    image->as_is = true;
    return true;
}

// File-system callbacks that refuse every file: memory loading without external files.
bool noFileExists(const std::string&, void*) { return false; }
std::string keepPath(const std::string& path, void*) { return path; }
bool noFileRead(std::vector<unsigned char>*, std::string* error, const std::string& path, void*)
{
    if (error)
        *error += "external file '" + path + "' not allowed when loading from memory\n";
    return false;
}
bool noFileWrite(std::string*, const std::string&, const std::vector<unsigned char>&, void*) { return false; }
// External buffers through the one input reader (core/InputFile.h): a FIFO or a device named
// as a buffer's uri is refused, not read for ever. Every file "exists" for tinygltf, so that it
// reads the path beside the model (not the one in the current directory it tries next) and the
// reader's message names the full path ("models/Sponza.bin: cannot open a buffer of
// models/Sponza.gltf: No such file or directory"), not tinygltf's "File not found : Sponza.bin".
struct ExternalFiles {
    std::string modelName;
    std::string firstError;  // the reader's message for the first file that could not be read
};
bool anyFileExists(const std::string&, void*) { return true; }
bool readExternalFile(std::vector<unsigned char>* bytes, std::string* error, const std::string& path, void* user)
{
    auto& files = *static_cast<ExternalFiles*>(user);
    try {
        *bytes = readInputBytes(path, "a buffer of " + files.modelName);
        return true;
    } catch (const Error& e) {
        if (files.firstError.empty())
            files.firstError = e.what();
        if (error)
            *error += std::string(e.what()) + "\n";
        return false;
    }
}

// A checked view of an accessor's elements inside its buffer.
struct AccessorView {
    const unsigned char* data = nullptr;
    std::size_t count = 0;
    std::size_t stride = 0;
    int componentType = 0;
    int components = 0;
    bool normalized = false;
};

class GltfReader {
public:
    // `warnings` holds what was noted before tinygltf read the file (scene/GltfFieldChecks.h).
    GltfReader(const tinygltf::Model& gltf, const std::string& displayName, const fs::path& baseDirectory,
               const GltfOptions& options, FileWarnings warnings)
        : gltf_(gltf),
          displayName_(displayName),
          base_(baseDirectory),
          options_(options),
          warnings_(std::move(warnings))
    {
    }

    Model read()
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

private:
    [[noreturn]] void fail(const std::string& what) const { throw Error(oneLine(displayName_ + ": " + what)); }

    // The extensions this loader reads. A file that requires another cannot be drawn as its
    // author meant (an error); one that only uses another is drawn without it (a warning).
    void checkExtensions()
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

    // --- nodes ---------------------------------------------------------------------------

    void checkHierarchy() const
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

    // The default scene's root nodes; without scenes, every node that is no node's child.
    std::vector<int> rootNodes() const
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

    glm::mat4 localMatrix(std::size_t index) const
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

    void visit(int nodeIndex, const glm::mat4& parent, int depth)
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

    // --- cameras -------------------------------------------------------------------------

    // A perspective camera looks down its node's −Z with +Y up (glTF 2.0, "Cameras"). Its
    // aspect ratio is the image's, as for the scene's camera; without zfar (an infinite
    // projection) the far plane is 1000 · znear beyond the default, whichever is larger.
    // Orthographic cameras have no counterpart in the scene's camera: passed over, with a warning.
    void addCamera(int cameraIndex, const glm::mat4& world, const std::string& name, std::size_t nodeIndex)
    {
        if (static_cast<std::size_t>(cameraIndex) >= gltf_.cameras.size())
            fail(element("nodes", nodeIndex) + ": camera " + std::to_string(cameraIndex) +
                 " is not a camera (the file has " + std::to_string(gltf_.cameras.size()) + ")");
        const tinygltf::Camera& source = gltf_.cameras[static_cast<std::size_t>(cameraIndex)];
        const std::string where = element("cameras", static_cast<std::size_t>(cameraIndex));
        if (source.type != "perspective") {
            warnings_.noteFile("camera " + source.type, where + ": type " + source.type +
                                                            " has no counterpart in the scene's camera; passed over");
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

    // --- lights --------------------------------------------------------------------------

    std::optional<std::size_t> punctualLight(const tinygltf::Node& node) const
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

    void addLight(std::size_t lightIndex, const glm::mat4& world, std::size_t nodeIndex)
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
        if (!std::isfinite(intensity.x + intensity.y + intensity.z) ||
            glm::any(glm::lessThan(intensity, glm::vec3{0.0f})))
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
            light.exponent = middle > 0.0 && middle < 1.0
                                 ? static_cast<float>(std::min(std::log(0.5) / std::log(middle), 128.0))
                                 : 0.0f;
        }
        model_.lights.push_back(light);
    }

    // --- accessors -----------------------------------------------------------------------

    AccessorView accessor(int index, const std::string& where) const
    {
        if (index < 0 || static_cast<std::size_t>(index) >= gltf_.accessors.size())
            fail(where + ": accessor " + std::to_string(index) + " is not an accessor (the file has " +
                 std::to_string(gltf_.accessors.size()) + ")");
        const tinygltf::Accessor& a = gltf_.accessors[static_cast<std::size_t>(index)];
        const std::string name = element("accessors", static_cast<std::size_t>(index));
        if (a.sparse.isSparse)
            fail(name + ": sparse accessors are not supported");
        if (a.bufferView < 0 || static_cast<std::size_t>(a.bufferView) >= gltf_.bufferViews.size())
            fail(name + ": bufferView " + std::to_string(a.bufferView) + " is not a buffer view (the file has " +
                 std::to_string(gltf_.bufferViews.size()) + ")");
        const tinygltf::BufferView& view = gltf_.bufferViews[static_cast<std::size_t>(a.bufferView)];
        const std::vector<unsigned char>& buffer = bufferOf(view, static_cast<std::size_t>(a.bufferView));
        const int componentSize = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType));
        const int components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
        if (componentSize <= 0 || components <= 0 || componentSize > 4)
            fail(name + ": unsupported componentType " + std::to_string(a.componentType) + " or type " +
                 std::to_string(a.type));
        const std::size_t elementSize = static_cast<std::size_t>(componentSize) * static_cast<std::size_t>(components);
        const std::size_t stride = view.byteStride != 0 ? view.byteStride : elementSize;
        if (stride < elementSize)
            fail(element("bufferViews", static_cast<std::size_t>(a.bufferView)) + ": byteStride " +
                 std::to_string(stride) + " is smaller than the element size " + std::to_string(elementSize) + " of " +
                 name);
        // Everything in 64-bit sizes, each step checked before it can overflow.
        if (a.byteOffset > view.byteLength ||
            (a.count > 0 && ((a.count - 1) > (view.byteLength - a.byteOffset) / stride ||
                             (a.count - 1) * stride + elementSize > view.byteLength - a.byteOffset)))
            fail(name + ": " + std::to_string(a.count) + " elements at byteOffset " + std::to_string(a.byteOffset) +
                 " do not fit in bufferViews[" + std::to_string(a.bufferView) + "] (" +
                 std::to_string(view.byteLength) + " bytes)");
        AccessorView result;
        result.data = buffer.data() + view.byteOffset + a.byteOffset;
        result.count = a.count;
        result.stride = stride;
        result.componentType = a.componentType;
        result.components = components;
        result.normalized = a.normalized;
        return result;
    }

    const std::vector<unsigned char>& bufferOf(const tinygltf::BufferView& view, std::size_t viewIndex) const
    {
        const std::string name = element("bufferViews", viewIndex);
        if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= gltf_.buffers.size())
            fail(name + ": buffer " + std::to_string(view.buffer) + " is not a buffer (the file has " +
                 std::to_string(gltf_.buffers.size()) + ")");
        const std::vector<unsigned char>& data = gltf_.buffers[static_cast<std::size_t>(view.buffer)].data;
        if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
            fail(name + ": bytes " + std::to_string(view.byteOffset) + " to " +
                 std::to_string(view.byteOffset + view.byteLength) + " lie outside buffers[" +
                 std::to_string(view.buffer) + "] (" + std::to_string(data.size()) + " bytes)");
        return data;
    }

    // Element i of a float (or normalised integer) accessor, `n` components.
    template <int N>
    glm::vec<N, float> readVector(const AccessorView& view, std::size_t i) const
    {
        glm::vec<N, float> result{0.0f};
        const unsigned char* at = view.data + i * view.stride;
        for (int k = 0; k < N; ++k) {
            switch (view.componentType) {
            case TINYGLTF_COMPONENT_TYPE_FLOAT: std::memcpy(&result[k], at + 4 * k, 4); break;
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: result[k] = static_cast<float>(at[k]) / 255.0f; break;
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
                std::uint16_t v;
                std::memcpy(&v, at + 2 * k, 2);
                result[k] = static_cast<float>(v) / 65535.0f;
                break;
            }
            default: break;
            }
        }
        return result;
    }

    // Checks that an attribute has the type the loader reads.
    void expectFormat(const AccessorView& view, int components, bool allowNormalizedInts,
                      const std::string& where) const
    {
        const bool floats = view.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
        const bool normalizedInts = allowNormalizedInts && view.normalized &&
                                    (view.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                     view.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
        if (view.components != components || !(floats || normalizedInts))
            fail(where + ": expected " + std::to_string(components) + " float components" +
                 (allowNormalizedInts ? " (or normalised unsigned bytes/shorts)" : "") + ", got componentType " +
                 std::to_string(view.componentType) + " with " + std::to_string(view.components));
    }

    // --- meshes --------------------------------------------------------------------------

    std::optional<std::size_t> meshFor(std::size_t meshIndex)
    {
        if (!meshOf_[meshIndex]) {
            Mesh mesh = readMesh(meshIndex);
            if (mesh.indices.empty()) {
                meshOf_[meshIndex] = kNoTriangles;
            } else {
                meshOf_[meshIndex] = model_.meshes.size();
                model_.meshes.push_back(std::move(mesh));
            }
        }
        if (*meshOf_[meshIndex] == kNoTriangles)
            return std::nullopt;
        return meshOf_[meshIndex];
    }

    Mesh readMesh(std::size_t meshIndex)
    {
        const tinygltf::Mesh& source = gltf_.meshes[meshIndex];
        Mesh mesh;
        mesh.name = displayName_ + "#" + (source.name.empty() ? element("meshes", meshIndex) : source.name);
        for (std::size_t p = 0; p < source.primitives.size(); ++p) {
            const std::string where = element("meshes", meshIndex) + "." + element("primitives", p);
            const std::size_t first = mesh.indices.size();
            readPrimitive(source.primitives[p], where, mesh);
            if (mesh.indices.size() == first)
                continue;
            SubMesh range;
            range.firstIndex = static_cast<std::uint32_t>(first);
            range.indexCount = static_cast<std::uint32_t>(mesh.indices.size() - first);
            range.material = materialFor(source.primitives[p].material, where);
            mesh.subMeshes.push_back(range);
        }
        return mesh;
    }

    // Appends the primitive's triangles to `mesh`. Points and lines are skipped (they have no
    // surface to light); strips and fans are turned into triangle lists.
    void readPrimitive(const tinygltf::Primitive& primitive, const std::string& where, Mesh& mesh)
    {
        const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
        if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
            mode != TINYGLTF_MODE_TRIANGLE_FAN) {
            if (mode >= TINYGLTF_MODE_POINTS && mode <= TINYGLTF_MODE_LINE_STRIP)
                return;
            fail(where + ": unknown mode " + std::to_string(mode));
        }
        const auto attribute = [&](const char* name) -> std::optional<AccessorView> {
            const auto found = primitive.attributes.find(name);
            if (found == primitive.attributes.end())
                return std::nullopt;
            return accessor(found->second, where + "." + name);
        };
        const auto positions = attribute("POSITION");
        if (!positions)
            fail(where + ": has no POSITION attribute");
        expectFormat(*positions, 3, false, where + ".POSITION");
        const std::size_t vertexCount = positions->count;
        const auto normals = attribute("NORMAL");
        const auto uvs = attribute("TEXCOORD_0");
        const auto tangents = attribute("TANGENT");
        const auto colours = attribute("COLOR_0");
        const auto sameCount = [&](const std::optional<AccessorView>& view, const char* name, int components,
                                   bool normalizedInts) {
            if (!view)
                return;
            expectFormat(*view, components, normalizedInts, where + "." + name);
            if (view->count != vertexCount)
                fail(where + "." + name + ": has " + std::to_string(view->count) + " elements, POSITION has " +
                     std::to_string(vertexCount));
        };
        sameCount(normals, "NORMAL", 3, false);
        sameCount(uvs, "TEXCOORD_0", 2, true);
        sameCount(tangents, "TANGENT", 4, false);
        if (colours) {
            // RGB or RGBA, floats or normalised unsigned bytes/shorts (glTF 2.0, "Meshes").
            sameCount(colours, "COLOR_0", colours->components == 3 ? 3 : 4, true);
            mesh.hasVertexColours = true;
        }

        // The primitive's corner list: its indices, or 0..n−1 when it has none.
        std::vector<std::uint32_t> corners;
        if (primitive.indices >= 0) {
            const AccessorView indices = accessor(primitive.indices, where + ".indices");
            if (indices.components != 1 || (indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                                            indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                                            indices.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
                fail(where + ".indices: expected unsigned byte, short or int scalars");
            corners.resize(indices.count);
            for (std::size_t i = 0; i < indices.count; ++i) {
                const unsigned char* at = indices.data + i * indices.stride;
                std::uint32_t value = 0;
                if (indices.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
                    value = at[0];
                } else if (indices.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
                    std::uint16_t v;
                    std::memcpy(&v, at, 2);
                    value = v;
                } else {
                    std::memcpy(&value, at, 4);
                }
                if (value >= vertexCount)
                    fail(where + ".indices: index " + std::to_string(i) + " is " + std::to_string(value) +
                         ", out of range (POSITION has " + std::to_string(vertexCount) + " elements)");
                corners[i] = value;
            }
        } else {
            if (vertexCount > std::numeric_limits<std::uint32_t>::max())
                fail(where + ": too many vertices for 32-bit indices");
            corners.resize(vertexCount);
            for (std::size_t i = 0; i < vertexCount; ++i)
                corners[i] = static_cast<std::uint32_t>(i);
        }
        if (mode == TINYGLTF_MODE_TRIANGLES && corners.size() % 3 != 0)
            fail(where + ": " + std::to_string(corners.size()) +
                 " corners are not whole triangles (not a multiple of 3)");
        const std::vector<std::uint32_t> triangles = triangleList(corners, mode);

        // glTF asks for flat normals when a primitive has none, so such a primitive gets three
        // vertices of its own per triangle; otherwise its vertices are shared as in the file.
        const bool flat = !normals;
        const auto vertexAt = [&](std::uint32_t i) {
            Vertex vertex{readVector<3>(*positions, i), glm::vec3{0.0f, 1.0f, 0.0f}, glm::vec2{0.0f}};
            if (!std::isfinite(vertex.position.x + vertex.position.y + vertex.position.z))
                fail(where + ".POSITION: element " + std::to_string(i) + " is not finite");
            if (normals) {
                const glm::vec3 n = readVector<3>(*normals, i);
                const float length = glm::length(n);
                if (!std::isfinite(length))
                    fail(where + ".NORMAL: element " + std::to_string(i) + " is not finite");
                vertex.normal = length > 0.0f ? n / length : glm::vec3{0.0f, 1.0f, 0.0f};
            }
            if (uvs) {
                vertex.uv = readVector<2>(*uvs, i);
                if (!std::isfinite(vertex.uv.x + vertex.uv.y))
                    fail(where + ".TEXCOORD_0: element " + std::to_string(i) + " is not finite");
                // glTF's uv origin is the image's top-left corner; ours (OBJ, GL, the texture
                // cache's bottom-up rows) the bottom-left.
                vertex.uv.y = 1.0f - vertex.uv.y;
            }
            if (colours) {
                vertex.colour =
                    colours->components == 3 ? glm::vec4(readVector<3>(*colours, i), 1.0f) : readVector<4>(*colours, i);
                if (!std::isfinite(vertex.colour.r + vertex.colour.g + vertex.colour.b + vertex.colour.a))
                    fail(where + ".COLOR_0: element " + std::to_string(i) + " is not finite");
                // Colours are linear and in [0, 1] by the specification; anything outside is clamped.
                vertex.colour = glm::clamp(vertex.colour, 0.0f, 1.0f);
            }
            if (tangents) {
                vertex.tangent = readVector<4>(*tangents, i);
                if (!std::isfinite(vertex.tangent.x + vertex.tangent.y + vertex.tangent.z + vertex.tangent.w))
                    fail(where + ".TANGENT: element " + std::to_string(i) + " is not finite");
                // w is the handedness, ±1 by the specification; anything else is read by its sign.
                // Flipping v above reverses the bitangent (the direction of increasing v), so
                // the handedness flips with it.
                vertex.tangent.w = vertex.tangent.w < 0.0f ? 1.0f : -1.0f;
            }
            return vertex;
        };
        const std::size_t base = mesh.vertices.size();
        std::vector<std::int64_t> slotOf(flat ? 0 : vertexCount, -1);
        const auto addCorner = [&](std::uint32_t i) {
            if (mesh.vertices.size() >= std::numeric_limits<std::uint32_t>::max())
                fail(where + ": too many vertices for 32-bit indices");
            if (flat) {
                mesh.indices.push_back(static_cast<std::uint32_t>(mesh.vertices.size()));
                mesh.vertices.push_back(vertexAt(i));
                return;
            }
            if (slotOf[i] < 0) {
                slotOf[i] = static_cast<std::int64_t>(mesh.vertices.size());
                mesh.vertices.push_back(vertexAt(i));
            }
            mesh.indices.push_back(static_cast<std::uint32_t>(slotOf[i]));
        };
        for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
            const glm::vec3 a = readVector<3>(*positions, triangles[t]);
            const glm::vec3 b = readVector<3>(*positions, triangles[t + 1]);
            const glm::vec3 c = readVector<3>(*positions, triangles[t + 2]);
            // Zero-area triangles draw nothing and have no normal: dropped, as in OBJ files.
            if (!std::isfinite(a.x + a.y + a.z + b.x + b.y + b.z + c.x + c.y + c.z))
                fail(where + ".POSITION: a triangle has a non-finite corner");
            if (isDegenerateTriangle(a, b, c))
                continue;
            for (std::size_t k = 0; k < 3; ++k)
                addCorner(triangles[t + k]);
        }
        if (flat) {
            for (std::size_t v = base; v + 2 < mesh.vertices.size(); v += 3) {
                const glm::vec3 n =
                    glm::normalize(glm::cross(mesh.vertices[v + 1].position - mesh.vertices[v].position,
                                              mesh.vertices[v + 2].position - mesh.vertices[v].position));
                for (std::size_t k = 0; k < 3; ++k)
                    mesh.vertices[v + k].normal = std::isfinite(n.x + n.y + n.z) ? n : glm::vec3{0.0f, 1.0f, 0.0f};
            }
        }
    }

    static std::vector<std::uint32_t> triangleList(const std::vector<std::uint32_t>& corners, int mode)
    {
        if (mode == TINYGLTF_MODE_TRIANGLES)
            return corners;
        std::vector<std::uint32_t> list;
        for (std::size_t i = 2; i < corners.size(); ++i) {
            if (mode == TINYGLTF_MODE_TRIANGLE_FAN)
                list.insert(list.end(), {corners[0], corners[i - 1], corners[i]});
            else if (i % 2 == 0)  // strip: every other triangle flips to keep the winding
                list.insert(list.end(), {corners[i - 2], corners[i - 1], corners[i]});
            else
                list.insert(list.end(), {corners[i - 1], corners[i - 2], corners[i]});
        }
        return list;
    }

    // --- materials -----------------------------------------------------------------------

    std::optional<std::size_t> materialFor(int index, const std::string& where)
    {
        if (index < 0)
            return std::nullopt;  // glTF's default material: the object's (or scene default) material
        if (static_cast<std::size_t>(index) >= gltf_.materials.size())
            fail(where + ": material " + std::to_string(index) + " is not a material (the file has " +
                 std::to_string(gltf_.materials.size()) + ")");
        auto& slot = materialOf_[static_cast<std::size_t>(index)];
        if (!slot) {
            slot = model_.materials.size();
            model_.materials.push_back(convertMaterial(static_cast<std::size_t>(index)));
        }
        return slot;
    }

    Material convertMaterial(std::size_t index)
    {
        const tinygltf::Material& source = gltf_.materials[index];
        const std::string where = element("materials", index);
        const auto colour = [&](const std::vector<double>& values, std::size_t size, const char* what) {
            if (values.size() < 3 || values.size() != size)
                fail(where + ": " + what + " needs " + std::to_string(size) + " numbers, has " +
                     std::to_string(values.size()));
            const glm::vec3 c(values[0], values[1], values[2]);
            if (!std::isfinite(c.x + c.y + c.z) || glm::any(glm::lessThan(c, glm::vec3{0.0f})))
                fail(where + ": " + what + " must be finite and not negative");
            return c;
        };
        const tinygltf::PbrMetallicRoughness& pbr = source.pbrMetallicRoughness;
        const glm::vec3 baseColour = colour(pbr.baseColorFactor, 4, "baseColorFactor");
        const auto metallic = static_cast<float>(pbr.metallicFactor);
        const auto roughness = static_cast<float>(pbr.roughnessFactor);
        if (!(metallic >= 0.0f && metallic <= 1.0f) || !(roughness >= 0.0f && roughness <= 1.0f))
            fail(where + ": metallicFactor and roughnessFactor must be in [0, 1]");
        Material material;
        material.name = displayName_ + "#" + (source.name.empty() ? where : source.name);
        // glTF's own model (docs/lighting.md); scene/MaterialModels.h maps it to Blinn-Phong for
        // a scene that asks for it (`"model_materials": "blinn-phong"`).
        material.model = ShadingModel::MetallicRoughness;
        material.baseColor = baseColour;
        material.metallicFactor = metallic;
        material.roughnessFactor = roughness;
        material.emissive = colour(source.emissiveFactor, 3, "emissiveFactor");
        material.diffuseMap = texturePath(pbr.baseColorTexture, where + ".baseColorTexture", material, kDiffuseSlot);
        material.metallicRoughnessMap =
            texturePath(pbr.metallicRoughnessTexture, where + ".metallicRoughnessTexture", material, kSpecularSlot);
        material.emissiveMap = texturePath(source.emissiveTexture, where + ".emissiveTexture", material, kEmissiveSlot);
        material.normalMap = texturePath(source.normalTexture, where + ".normalTexture", material, kNormalSlot);
        material.normalScale = static_cast<float>(source.normalTexture.scale);
        if (!std::isfinite(material.normalScale))
            fail(where + ".normalTexture: scale is not finite");
        material.occlusionMap =
            texturePath(source.occlusionTexture, where + ".occlusionTexture", material, kOcclusionSlot);
        material.occlusionStrength = static_cast<float>(source.occlusionTexture.strength);
        if (!(material.occlusionStrength >= 0.0f && material.occlusionStrength <= 1.0f))
            fail(where + ".occlusionTexture: strength must be in [0, 1]");
        if (const auto found = source.extensions.find("KHR_materials_emissive_strength");
            found != source.extensions.end() && found->second.Has("emissiveStrength")) {
            const tinygltf::Value& strength = found->second.Get("emissiveStrength");
            const double value = strength.IsNumber() || strength.IsInt() ? strength.GetNumberAsDouble() : -1.0;
            if (!(value >= 0.0) || !std::isfinite(value))
                fail(where + ": KHR_materials_emissive_strength.emissiveStrength must be a finite number >= 0");
            material.emissive *= static_cast<float>(value);
        }
        readCoverage(source, where, material);
        material.sides = source.doubleSided ? Sides::BothFlipped : Sides::Front;
        return material;
    }

    // alphaMode, alphaCutoff and the base colour's alpha.
    void readCoverage(const tinygltf::Material& source, const std::string& where, Material& material)
    {
        const double alpha = source.pbrMetallicRoughness.baseColorFactor[3];
        if (!std::isfinite(alpha) || alpha < 0.0)
            fail(where + ": baseColorFactor's alpha must be a finite number >= 0");
        material.opacity = static_cast<float>(std::min(alpha, 1.0));
        if (source.alphaMode == "MASK") {
            if (!std::isfinite(source.alphaCutoff) || source.alphaCutoff < 0.0)
                fail(where + ": alphaCutoff must be a finite number >= 0");
            material.alphaMode = AlphaMode::Mask;
            material.alphaCutoff = static_cast<float>(source.alphaCutoff);
        } else if (source.alphaMode == "BLEND") {
            material.alphaMode = AlphaMode::Blend;
        } else if (source.alphaMode != "OPAQUE") {
            warnings_.noteFile("alphaMode " + source.alphaMode,
                               where + ": unknown alphaMode '" + source.alphaMode + "'; drawn OPAQUE");
        }
    }

    // A texture reference's path, with its KHR_texture_transform (if any) stored in the
    // material's slot. Only TEXCOORD_0 is read: another set is drawn with it, with a warning.
    template <typename TextureReference>
    std::string texturePath(const TextureReference& reference, const std::string& where, Material& material,
                            MaterialMapSlot slot)
    {
        if (reference.index < 0)
            return {};
        int texCoord = reference.texCoord;
        if (const auto found = reference.extensions.find("KHR_texture_transform");
            found != reference.extensions.end()) {
            material.uvTransforms[slot] = uvTransform(found->second, where + ".KHR_texture_transform");
            const tinygltf::Value& set = found->second.Get("texCoord");
            if (set.IsInt())
                texCoord = set.GetNumberAsInt();
        }
        if (texCoord != 0)
            warnings_.noteFile("texCoord", where + ": texCoord " + std::to_string(texCoord) +
                                               " is not read; the texture is drawn with TEXCOORD_0");
        std::string path = texturePath(reference.index, where);
        material.wraps[slot] = samplerWrap(gltf_.textures[static_cast<std::size_t>(reference.index)].sampler);
        return path;
    }

    // KHR_texture_transform's uv' = T · R · S · uv in glTF's uv convention (origin at the top
    // left), conjugated by the v flip readPrimitive applies (F: v → 1 − v, its own inverse), so
    // that it applies to our uvs: F · T · R · S · F.
    glm::mat3 uvTransform(const tinygltf::Value& extension, const std::string& where) const
    {
        const auto numbers = [&](const char* key, glm::vec2 fallback) {
            const tinygltf::Value& value = extension.Get(key);
            if (!value.IsArray())
                return fallback;
            if (value.ArrayLen() != 2 || !value.Get(0).IsNumber() || !value.Get(1).IsNumber())
                fail(where + ": " + key + " needs 2 numbers");
            return glm::vec2(value.Get(0).GetNumberAsDouble(), value.Get(1).GetNumberAsDouble());
        };
        const glm::vec2 offset = numbers("offset", glm::vec2{0.0f});
        const glm::vec2 scale = numbers("scale", glm::vec2{1.0f});
        const tinygltf::Value& rotationValue = extension.Get("rotation");
        const float rotation = rotationValue.IsNumber() ? static_cast<float>(rotationValue.GetNumberAsDouble()) : 0.0f;
        if (!std::isfinite(offset.x + offset.y + scale.x + scale.y + rotation))
            fail(where + ": offset, rotation and scale must be finite");
        // glm matrices are column-major: m[column][row].
        glm::mat3 translation{1.0f};
        translation[2] = glm::vec3(offset, 1.0f);
        glm::mat3 turn{1.0f};
        turn[0] = glm::vec3(std::cos(rotation), -std::sin(rotation), 0.0f);
        turn[1] = glm::vec3(std::sin(rotation), std::cos(rotation), 0.0f);
        glm::mat3 scaling{1.0f};
        scaling[0][0] = scale.x;
        scaling[1][1] = scale.y;
        glm::mat3 flip{1.0f};
        flip[1][1] = -1.0f;
        flip[2][1] = 1.0f;
        return flip * translation * turn * scaling * flip;
    }

    // The path (or Scene::encodedImages key) of a texture's image; empty without a texture.
    std::string texturePath(int textureIndex, const std::string& where)
    {
        if (textureIndex < 0)
            return {};
        if (static_cast<std::size_t>(textureIndex) >= gltf_.textures.size())
            fail(where + ": texture " + std::to_string(textureIndex) + " is not a texture (the file has " +
                 std::to_string(gltf_.textures.size()) + ")");
        const int source = gltf_.textures[static_cast<std::size_t>(textureIndex)].source;
        if (source < 0)
            return {};  // a texture without an image (e.g. only an extension's): none
        if (static_cast<std::size_t>(source) >= gltf_.images.size())
            fail(element("textures", static_cast<std::size_t>(textureIndex)) + ": source " + std::to_string(source) +
                 " is not an image (the file has " + std::to_string(gltf_.images.size()) + ")");
        auto& path = imagePathOf_[static_cast<std::size_t>(source)];
        if (!path)
            path = imagePath(static_cast<std::size_t>(source));
        return *path;
    }

    // A texture's sampler's wrap modes (none: repeat, glTF's default). Its filters are not
    // read: every map is filtered trilinearly or anisotropically (--anisotropy).
    MapWrap samplerWrap(int samplerIndex)
    {
        if (samplerIndex < 0)
            return {};
        if (static_cast<std::size_t>(samplerIndex) >= gltf_.samplers.size())
            fail("a texture's sampler " + std::to_string(samplerIndex) + " is not a sampler (the file has " +
                 std::to_string(gltf_.samplers.size()) + ")");
        const tinygltf::Sampler& sampler = gltf_.samplers[static_cast<std::size_t>(samplerIndex)];
        const auto wrap = [&](int mode, const char* axis) {
            switch (mode) {
            case TINYGLTF_TEXTURE_WRAP_REPEAT: return TextureWrap::Repeat;
            case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return TextureWrap::ClampToEdge;
            case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return TextureWrap::MirroredRepeat;
            default:
                warnings_.noteFile("sampler wrap", element("samplers", static_cast<std::size_t>(samplerIndex)) +
                                                       ": unknown " + axis + " " + std::to_string(mode) +
                                                       "; drawn with REPEAT");
                return TextureWrap::Repeat;
            }
        };
        return {wrap(sampler.wrapS, "wrapS"), wrap(sampler.wrapT, "wrapT")};
    }

    std::string imagePath(std::size_t index)
    {
        const tinygltf::Image& image = gltf_.images[index];
        const std::string name = element("images", index);
        EncodedImage encoded;
        encoded.key = displayName_ + "#" + name;
        encoded.mimeType = image.mimeType;
        if (image.bufferView >= 0) {
            if (static_cast<std::size_t>(image.bufferView) >= gltf_.bufferViews.size())
                fail(name + ": bufferView " + std::to_string(image.bufferView) + " is not a buffer view");
            const tinygltf::BufferView& view = gltf_.bufferViews[static_cast<std::size_t>(image.bufferView)];
            const std::vector<unsigned char>& buffer = bufferOf(view, static_cast<std::size_t>(image.bufferView));
            const auto begin = buffer.begin() + static_cast<std::ptrdiff_t>(view.byteOffset);
            encoded.bytes.assign(begin, begin + static_cast<std::ptrdiff_t>(view.byteLength));
        } else if (!image.image.empty()) {
            encoded.bytes = image.image;
        } else {
            // An external image: only its existence is checked; the render layer decodes it.
            if (image.uri.empty())
                fail(name + ": has neither a uri nor a bufferView");
            if (!options_.allowExternalFiles)
                fail(name + ": external image '" + image.uri + "' not allowed when loading from memory");
            const fs::path path = base_ / image.uri;
            std::error_code error;
            if (!fs::is_regular_file(path, error))
                fail(name + ": image file '" + image.uri + "' not found (" + path.string() + ")");
            return path.string();
        }
        if (encoded.bytes.empty())
            fail(name + ": the embedded image is empty");
        model_.images.push_back(std::move(encoded));
        return model_.images.back().key;
    }

    static constexpr std::size_t kNoTriangles = std::numeric_limits<std::size_t>::max();

    const tinygltf::Model& gltf_;
    std::string displayName_;
    fs::path base_;
    GltfOptions options_;
    FileWarnings warnings_;  // flushed into options_.warnings once the file has loaded
    Model model_;
    std::vector<std::optional<std::size_t>> meshOf_;      // glTF mesh → Model::meshes
    std::vector<std::optional<std::size_t>> materialOf_;  // glTF material → Model::materials
    std::vector<std::optional<std::string>> imagePathOf_;
    std::vector<bool> onPath_;  // nodes between the root and the node being visited
};

bool isBinaryGltf(const std::vector<unsigned char>& bytes)
{
    return bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
}

// tinygltf parses extras and extensions recursively and overflows the stack somewhere past
// 10,000 levels; no real file nests deeper than a few dozen. Checked on the text first.
constexpr int kMaxGltfJsonDepth = 512;

void checkJsonNesting(std::string_view json, const std::string& displayName)
{
    int depth = 0;
    int line = 1;
    std::size_t lineStart = 0;
    bool inString = false;
    for (std::size_t i = 0; i < json.size(); ++i) {
        const char c = json[i];
        if (c == '\n') {
            ++line;
            lineStart = i + 1;
        } else if (inString) {
            if (c == '\\')
                ++i;  // the escaped character cannot end the string
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '{' || c == '[') {
            if (++depth > kMaxGltfJsonDepth)
                throw Error(displayName + ":" + std::to_string(line) + ":" + std::to_string(i - lineStart + 1) +
                            ": JSON nested deeper than " + std::to_string(kMaxGltfJsonDepth) + " levels");
        } else if (c == '}' || c == ']') {
            --depth;
        }
    }
}

// The JSON text of a .gltf file, or of a .glb file's first chunk (empty if it has none).
std::string_view gltfJsonText(const std::vector<unsigned char>& bytes)
{
    const char* data = reinterpret_cast<const char*>(bytes.data());
    if (!isBinaryGltf(bytes))
        return {data, bytes.size()};
    constexpr std::size_t kChunkStart = 20;  // 12-byte header, chunk length and type
    if (bytes.size() < kChunkStart)
        return {};
    std::uint32_t length = 0;
    std::memcpy(&length, data + 12, sizeof length);  // little-endian, as the format and x86
    return {data + kChunkStart, std::min<std::size_t>(length, bytes.size() - kChunkStart)};
}

}  // namespace

Model loadGltfMemory(const std::vector<unsigned char>& bytes, const std::string& displayName,
                     const fs::path& baseDirectory, const GltfOptions& options)
{
    if (bytes.size() > std::numeric_limits<unsigned int>::max())
        throw Error(displayName + ": the file is too large (over 4 GiB)");
    // tinygltf reads the .glb container's version without checking it; version 1 (glTF 1.0)
    // and anything newer are laid out differently.
    if (isBinaryGltf(bytes) && bytes.size() >= 8) {
        std::uint32_t version = 0;
        std::memcpy(&version, bytes.data() + 4, sizeof version);
        if (version != 2)
            throw Error(displayName + ": a .glb container of version " + std::to_string(version) +
                        "; only version 2 (glTF 2.0) is read");
    }
    checkJsonNesting(gltfJsonText(bytes), displayName);
    FileWarnings warnings(displayName);
    checkGltfFields(gltfJsonText(bytes), warnings);
    tinygltf::TinyGLTF context;
    context.SetImageLoader(&keepEncodedImage, nullptr);
    ExternalFiles externalFiles{displayName, {}};
    if (options.allowExternalFiles)
        context.SetFsCallbacks({&anyFileExists, &keepPath, &readExternalFile, &noFileWrite, &externalFiles});
    else
        context.SetFsCallbacks({&noFileExists, &keepPath, &noFileRead, &noFileWrite, nullptr});
    tinygltf::Model gltf;
    std::string error;
    std::string warning;
    const auto length = static_cast<unsigned int>(bytes.size());
    // tinygltf wants a base directory string; "" would mean the current directory.
    const std::string base = baseDirectory.empty() ? std::string(".") : baseDirectory.string();
    bool ok = false;
    try {
        ok = isBinaryGltf(bytes)
                 ? context.LoadBinaryFromMemory(&gltf, &error, &warning, bytes.data(), length, base)
                 : context.LoadASCIIFromString(&gltf, &error, &warning, reinterpret_cast<const char*>(bytes.data()),
                                               length, base);
    } catch (const std::exception& e) {
        // tinygltf's JSON library may still throw on values it cannot represent.
        throw Error(oneLine(displayName + ": " + e.what()));
    }
    if (!ok || !error.empty()) {
        if (!externalFiles.firstError.empty())
            throw Error(oneLine(externalFiles.firstError));
        std::string message = error.empty() ? std::string("cannot parse the file") : error;
        message = message.substr(0, message.find('\n'));
        throw Error(oneLine(displayName + ": " + message));
    }
    return GltfReader(gltf, displayName, baseDirectory, options, std::move(warnings)).read();
}

Model loadGltfFile(const fs::path& path, const GltfOptions& options)
{
    return loadGltfMemory(readInputBytes(path, "the file"), path.string(), path.parent_path(), options);
}

}  // namespace manylights
