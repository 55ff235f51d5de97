#include "scene/GltfFieldChecks.h"

#include <cctype>
#include <string>

#include "scene/JsonText.h"

namespace manylights {

namespace {

using scene_json::describeType;
using scene_json::describeValue;
using scene_json::escapePointerToken;
using scene_json::Json;

// What tinygltf makes of a field that breaks its rule, said after the rule so that the
// warning tells what is drawn.
constexpr const char* kNotRead = "; the field is not read";
constexpr const char* kReadAsNone = "; read as none";

// The arrays of the top-level glTF object whose elements are objects with an optional name.
constexpr const char* kTopLevelArrays[] = {"accessors", "animations", "buffers", "bufferViews", "cameras",
                                           "images",    "materials",  "meshes",  "nodes",       "samplers",
                                           "scenes",    "skins",      "textures"};

// A pointer with its array indices replaced by '*': the kind a warning is gathered under, so
// that ten thousand nodes named by numbers give one warning ("... (and 9999 more)").
std::string kindOf(const std::string& pointer, const std::string& problem)
{
    std::string kind;
    bool inIndex = false;
    for (std::size_t i = 0; i < pointer.size(); ++i) {
        const bool digit = std::isdigit(static_cast<unsigned char>(pointer[i])) != 0;
        const bool tokenStart = i > 0 && pointer[i - 1] == '/';
        if (digit && (tokenStart || inIndex)) {
            if (!inIndex)
                kind += '*';
            inIndex = true;
            continue;
        }
        inIndex = false;
        kind += pointer[i];
    }
    return "schema " + kind + " " + problem;
}

class FieldChecker {
public:
    explicit FieldChecker(FileWarnings& warnings) : warnings_(warnings) {}

    void checkRoot(const Json& root)
    {
        if (!root.is_object())
            return;  // tinygltf says so
        index(root, "", "scene");
        extensions(root, "");
        for (const char* name : kTopLevelArrays) {
            std::string pointer = "/";
            pointer += name;
            if (!array(root, "", name))
                continue;
            const Json& elements = root[name];
            for (std::size_t i = 0; i < elements.size(); ++i) {
                const std::string at = pointer + "/" + std::to_string(i);
                if (!elements[i].is_object()) {
                    note(at, name + std::string(" elements must be objects, got ") + describeType(elements[i]),
                         kNotRead);
                    continue;
                }
                string(elements[i], at, "name");
                extensions(elements[i], at);
                checkElement(name, elements[i], at);
            }
        }
        if (const Json* ext = member(root, "extensions"); ext && ext->is_object())
            if (const Json* lights = member(*ext, "KHR_lights_punctual"))
                punctualLights(*lights, "/extensions/KHR_lights_punctual");
    }

private:
    static const Json* member(const Json& parent, const char* key)
    {
        if (!parent.is_object())
            return nullptr;
        const auto found = parent.find(key);
        return found == parent.end() ? nullptr : &*found;
    }

    void note(const std::string& pointer, const std::string& problem, const char* result)
    {
        warnings_.noteFile(kindOf(pointer, problem.substr(0, problem.find(", got"))),
                           pointer + ": " + problem + result);
    }

    static std::string at(const std::string& pointer, const std::string& key)
    {
        return pointer + "/" + escapePointerToken(key);
    }

    // Each returns true when the field is there and of its type.
    bool typed(const Json& parent, const std::string& pointer, const char* key, bool (Json::*is)() const noexcept,
               const char* expected)
    {
        const Json* value = member(parent, key);
        if (value == nullptr)
            return false;
        if (((*value).*is)())
            return true;
        note(at(pointer, key), std::string(key) + " must be " + expected + ", got " + describeValue(*value), kNotRead);
        return false;
    }
    bool object(const Json& p, const std::string& ptr, const char* key)
    {
        return typed(p, ptr, key, &Json::is_object, "an object");
    }
    bool array(const Json& p, const std::string& ptr, const char* key)
    {
        return typed(p, ptr, key, &Json::is_array, "an array");
    }
    void string(const Json& p, const std::string& ptr, const char* key)
    {
        typed(p, ptr, key, &Json::is_string, "a string");
    }
    void boolean(const Json& p, const std::string& ptr, const char* key)
    {
        typed(p, ptr, key, &Json::is_boolean, "a boolean");
    }
    void number(const Json& p, const std::string& ptr, const char* key)
    {
        typed(p, ptr, key, &Json::is_number, "a number");
    }
    void numbers(const Json& p, const std::string& ptr, const char* key)
    {
        if (!array(p, ptr, key))
            return;
        const Json& values = p[key];
        for (std::size_t i = 0; i < values.size(); ++i)
            if (!values[i].is_number())
                note(at(ptr, key) + "/" + std::to_string(i),
                     std::string(key) + " must hold numbers, got " + describeValue(values[i]), kNotRead);
    }

    // An index into one of the file's arrays (or a count): an integer ≥ 0.
    void indexValue(const Json& value, const std::string& pointer, const std::string& field)
    {
        if (value.is_number_unsigned())
            return;
        if (value.is_number_integer())
            note(pointer, field + " must be an integer ≥ 0, got " + describeValue(value), kReadAsNone);
        else
            note(pointer, field + " must be an integer ≥ 0, got " + describeValue(value), kNotRead);
    }
    void index(const Json& p, const std::string& ptr, const char* key)
    {
        if (const Json* value = member(p, key))
            indexValue(*value, at(ptr, key), key);
    }
    void indices(const Json& p, const std::string& ptr, const char* key)
    {
        if (!array(p, ptr, key))
            return;
        const Json& values = p[key];
        for (std::size_t i = 0; i < values.size(); ++i)
            indexValue(values[i], at(ptr, key) + "/" + std::to_string(i), key);
    }

    // An `extensions` member is an object of objects.
    void extensions(const Json& p, const std::string& ptr)
    {
        if (!object(p, ptr, "extensions"))
            return;
        for (const auto& [name, value] : p["extensions"].items())
            if (!value.is_object())
                note(at(at(ptr, "extensions"), name), name + " must be an object, got " + describeValue(value),
                     kNotRead);
    }

    // normalTexture, baseColorTexture, ...: {index, texCoord, scale | strength}.
    void textureInfo(const Json& p, const std::string& ptr, const char* key)
    {
        if (!object(p, ptr, key))
            return;
        const Json& info = p[key];
        const std::string where = at(ptr, key);
        index(info, where, "index");
        index(info, where, "texCoord");
        number(info, where, "scale");
        number(info, where, "strength");
        extensions(info, where);
    }

    void checkElement(const std::string& section, const Json& e, const std::string& ptr)
    {
        if (section == "accessors") {
            index(e, ptr, "bufferView");
            index(e, ptr, "byteOffset");
            index(e, ptr, "count");
            string(e, ptr, "type");
            boolean(e, ptr, "normalized");
        } else if (section == "bufferViews") {
            index(e, ptr, "buffer");
            index(e, ptr, "byteOffset");
            index(e, ptr, "byteLength");
            index(e, ptr, "byteStride");
        } else if (section == "buffers") {
            string(e, ptr, "uri");
            index(e, ptr, "byteLength");
        } else if (section == "images") {
            string(e, ptr, "uri");
            string(e, ptr, "mimeType");
            index(e, ptr, "bufferView");
        } else if (section == "materials") {
            if (object(e, ptr, "pbrMetallicRoughness")) {
                const Json& pbr = e["pbrMetallicRoughness"];
                const std::string where = at(ptr, "pbrMetallicRoughness");
                numbers(pbr, where, "baseColorFactor");
                number(pbr, where, "metallicFactor");
                number(pbr, where, "roughnessFactor");
                textureInfo(pbr, where, "baseColorTexture");
                textureInfo(pbr, where, "metallicRoughnessTexture");
            }
            textureInfo(e, ptr, "normalTexture");
            textureInfo(e, ptr, "occlusionTexture");
            textureInfo(e, ptr, "emissiveTexture");
            numbers(e, ptr, "emissiveFactor");
            string(e, ptr, "alphaMode");
            number(e, ptr, "alphaCutoff");
            boolean(e, ptr, "doubleSided");
        } else if (section == "meshes") {
            if (!array(e, ptr, "primitives"))
                return;
            const Json& primitives = e["primitives"];
            for (std::size_t i = 0; i < primitives.size(); ++i) {
                const std::string where = at(ptr, "primitives") + "/" + std::to_string(i);
                if (!primitives[i].is_object()) {
                    note(where, "primitives elements must be objects, got " + describeType(primitives[i]), kNotRead);
                    continue;
                }
                if (object(primitives[i], where, "attributes"))
                    for (const auto& [name, value] : primitives[i]["attributes"].items())
                        indexValue(value, at(at(where, "attributes"), name), name);
                index(primitives[i], where, "indices");
                index(primitives[i], where, "material");
                index(primitives[i], where, "mode");
            }
        } else if (section == "nodes") {
            index(e, ptr, "camera");
            index(e, ptr, "mesh");
            index(e, ptr, "skin");
            indices(e, ptr, "children");
            numbers(e, ptr, "matrix");
            numbers(e, ptr, "rotation");
            numbers(e, ptr, "scale");
            numbers(e, ptr, "translation");
            if (const Json* ext = member(e, "extensions"); ext && ext->is_object())
                if (const Json* light = member(*ext, "KHR_lights_punctual"); light && light->is_object())
                    index(*light, at(at(ptr, "extensions"), "KHR_lights_punctual"), "light");
        } else if (section == "scenes") {
            indices(e, ptr, "nodes");
        } else if (section == "textures") {
            index(e, ptr, "sampler");
            index(e, ptr, "source");
        } else if (section == "samplers") {
            index(e, ptr, "magFilter");
            index(e, ptr, "minFilter");
            index(e, ptr, "wrapS");
            index(e, ptr, "wrapT");
        } else if (section == "cameras") {
            string(e, ptr, "type");
        }
    }

    // KHR_lights_punctual: range > 0 when given (a range of 0 reads as no range).
    void punctualLights(const Json& extension, const std::string& ptr)
    {
        if (!extension.is_object() || !array(extension, ptr, "lights"))
            return;
        const Json& lights = extension["lights"];
        for (std::size_t i = 0; i < lights.size(); ++i) {
            const std::string where = at(ptr, "lights") + "/" + std::to_string(i);
            if (!lights[i].is_object()) {
                note(where, "lights elements must be objects, got " + describeType(lights[i]), kNotRead);
                continue;
            }
            const Json& light = lights[i];
            string(light, where, "name");
            string(light, where, "type");
            numbers(light, where, "color");
            number(light, where, "intensity");
            if (const Json* range = member(light, "range"); range && range->is_number()) {
                if (range->get<double>() == 0.0)
                    note(at(where, "range"), "range must be > 0, got 0",
                         "; the light is drawn as one without a range (inverse-square, cut at the scene's "
                         "attenuation_threshold)");
            } else {
                number(light, where, "range");
            }
            if (object(light, where, "spot")) {
                number(light["spot"], at(where, "spot"), "innerConeAngle");
                number(light["spot"], at(where, "spot"), "outerConeAngle");
            }
        }
    }

    FileWarnings& warnings_;
};

}  // namespace

void checkGltfFields(std::string_view json, FileWarnings& warnings)
{
    const Json root = Json::parse(json.begin(), json.end(), nullptr, false);
    if (root.is_discarded())
        return;
    FieldChecker(warnings).checkRoot(root);
}

}  // namespace manylights
