// Reads a scene file (docs/scene-format.md) strictly: every unknown key, wrong type, wrong length,
// non-finite or out-of-range value and missing file is an Error whose message names the file
// and the line:column (syntax errors) or the JSON path (everything else).
#pragma once

#include <filesystem>
#include <string>

#include "scene/Scene.h"

namespace manylights {

struct SceneLoadOptions {
    // --strict: the first problem a model file has that is otherwise forgiven (scene/Warnings.h)
    // is an error.
    bool strict = false;
};

// Loads and validates the scene file at `path`; meshes are loaded relative to it. What model
// files get forgiven is in Scene::warnings.
Scene loadSceneFile(const std::filesystem::path& path, const SceneLoadOptions& options = {});

// Parses scene JSON text. `displayName` is used in messages; relative paths inside the
// scene resolve against `baseDirectory`.
Scene parseScene(const std::string& jsonText, const std::string& displayName,
                 const std::filesystem::path& baseDirectory, const SceneLoadOptions& options = {});

}  // namespace manylights
