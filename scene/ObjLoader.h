// OBJ + MTL model files (docs/scene-format.md, "Model files"): every group of the file in one
// indexed mesh, with one sub-mesh (draw range) per material the faces use.
#pragma once

#include <filesystem>
#include <functional>
#include <istream>
#include <optional>
#include <string>

#include "scene/Model.h"
#include "scene/Warnings.h"

namespace manylights {

// Reads the text of a material library named by an OBJ file's `mtllib`: nullopt when there is
// no such file.
using MtlSource = std::function<std::optional<std::string>(const std::string& name)>;

// Loads an OBJ file and the .mtl libraries it names (relative to its directory), texture maps
// relative to the library. What other readers forgive goes into `warnings`, one line each
// naming the file and line (docs/scene-format.md, "OBJ and MTL"), and the model still loads:
// a missing library or map, an unknown `usemtl`, Windows separators or another letter case in
// a map's path, one-value colours, '+' signs, a byte-order mark or UTF-16 text, unknown
// statements. Throws Error naming the file (and the line where one is known) where nothing
// sensible can be drawn: no faces, non-finite or unreadable numbers, indices out of range.
Model loadObjModelFile(const std::filesystem::path& path, Warnings& warnings);

// The same from text in memory. `mtlSource` empty: `mtllib` and `usemtl` are ignored (the
// mesh has no sub-meshes). Texture paths resolve against `baseDirectory`.
Model loadObjModelText(const std::string& text, const std::string& displayName,
                       const std::filesystem::path& baseDirectory, const MtlSource& mtlSource, Warnings& warnings);

// Loads the geometry of an OBJ file (all groups merged into one indexed mesh; materials
// ignored: loadObjModelFile reads those). Smooth, area-weighted normals are computed where the
// file has none. Throws Error naming the file on I/O errors, malformed content, out-of-range
// indices or non-finite positions.
Mesh loadObjFile(const std::filesystem::path& path);
Mesh loadObjStream(std::istream& stream, const std::string& displayName);

}  // namespace manylights
