// The scene file's reading primitives (docs/scene-format.md): every JSON value is read
// through a Node that knows its JSON pointer, so each error names the file and the place in
// it ("FILE: /objects/3/mesh: what"); the readers check types, ranges and counts. The files
// of the scene loader's sections (scene/SceneFileLoader.h) build on it; nothing outside
// scene/ includes it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "core/Error.h"
#include "scene/JsonText.h"
#include "scene/Scene.h"

namespace manylights::scene_file {

namespace fs = std::filesystem;
using scene_json::Json;

// A JSON value and its JSON pointer (RFC 6901), which every message names.
struct Node {
    const Json* json;
    std::string path;
};

class Reader {
public:
    Reader(std::string displayName, fs::path baseDirectory)
        : displayName_(std::move(displayName)), base_(std::move(baseDirectory))
    {
    }

    using Keys = std::initializer_list<std::string_view>;
    using NumberReader = float (Reader::*)(const Node&) const;

    // "FILE: /json/pointer: what", the form of every error and warning about the scene.
    std::string located(const Node& node, const std::string& what) const;

    [[noreturn]] void fail(const Node& node, const std::string& what) const { throw Error(located(node, what)); }

    // --- structure ---------------------------------------------------------------
    static std::optional<Node> member(const Node& object, std::string_view key);
    Node required(const Node& object, std::string_view key) const;
    static Node element(const Node& array, std::size_t index);
    void expectObject(const Node& node) const;
    void expectArray(const Node& node, std::size_t maxSize, const char* what) const;

    // Unknown keys are errors: a misspelt key would otherwise silently render another scene.
    void expectKeys(const Node& object, Keys known) const;

    // --- scalars -----------------------------------------------------------------
    // Every number becomes a float on the GPU; one that overflows a float would turn into an
    // infinity there, so it is rejected here.
    float number(const Node& node) const;

    float positive(const Node& node) const;
    float nonNegative(const Node& node) const;
    float nonZero(const Node& node) const;
    float shininess(const Node& node) const;
    float cutoff(const Node& node) const;
    float fraction(const Node& node) const;
    std::int64_t integer(const Node& node, std::int64_t lo, std::int64_t hi) const;
    std::string string(const Node& node) const;

    // A string that must be one of `names`; an unknown one is named with the closest.
    std::string oneOf(const Node& node, const std::vector<std::string>& names) const;

    bool boolean(const Node& node) const;
    float optionalNumber(const Node& node, std::string_view key, float fallback, NumberReader reader) const;

    // --- vectors and intervals ---------------------------------------------------
    void expectNumberArray(const Node& node, std::size_t count) const;
    glm::vec3 vec3(const Node& node, NumberReader component = &Reader::number) const;
    glm::vec3 colour(const Node& node) const { return vec3(node, &Reader::nonNegative); }

    // A direction must be normalisable in float: a zero vector, or one whose squared length
    // underflows or overflows, has no direction.
    glm::vec3 direction(const Node& node) const;

    Interval interval(const Node& node, NumberReader bound) const;
    Interval numberOrInterval(const Node& node, NumberReader bound) const;

    // --- files -------------------------------------------------------------------
    fs::path resolve(const Node& node) const;

    // Where a missing file lies in a folder a Debian package installs, the package to install:
    // the example scenes use real models from assimp-testmodels (docs/scene-format.md).
    static std::string packageHint(const fs::path& path);

    void expectRegularFile(const Node& node, const fs::path& path) const;

    // --- animation ---------------------------------------------------------------
    // An animation is an object with exactly one key, the kind, whose value holds its settings.
    std::pair<std::string, Node> animationKind(const Node& node, const std::vector<std::string>& kinds) const;

protected:
    std::string displayName_;
    fs::path base_;  // relative paths in the file are resolved against it
};

}  // namespace manylights::scene_file
