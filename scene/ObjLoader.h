// OBJ + MTL model files (docs/scene-format.md, "Model files"): every group of the file in one
// indexed mesh, with one sub-mesh (draw range) per material the faces use.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "scene/Model.h"

namespace manylights {

// Reads the text of a material library named by an OBJ file's `mtllib`: nullopt when there is
// no such file.
using MtlSource = std::function<std::optional<std::string>(const std::string& name)>;

// Loads an OBJ file and the .mtl libraries it names (relative to its directory). Texture maps
// are resolved relative to the file and must exist. Throws Error naming the file (and the
// line where one is known) on any problem.
Model loadObjModelFile(const std::filesystem::path& path);

// The same from text in memory. `mtlSource` empty: `mtllib` and `usemtl` are ignored (the
// mesh has no sub-meshes). Texture paths resolve against `baseDirectory`.
Model loadObjModelText(const std::string& text, const std::string& displayName,
                       const std::filesystem::path& baseDirectory, const MtlSource& mtlSource);

}  // namespace manylights
