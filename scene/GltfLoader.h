// glTF 2.0 model files (.gltf with external or embedded buffers, and .glb) through tinygltf:
// node hierarchy, meshes with several primitives, metallic-roughness materials mapped to the
// Blinn-Phong material, and KHR_lights_punctual lights. Rules: docs/scene-format.md, "Model
// files".
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "scene/Model.h"
#include "scene/Warnings.h"

namespace manylights {

struct GltfOptions {
    // The scene's attenuation_threshold: a punctual light without `range` gets the radius at
    // which its inverse-square intensity falls to it.
    float attenuationThreshold = kDefaultAttenuationThreshold;
    // When false, buffers and images are never read from disk (a URI that is not a data: URI
    // is an error), so loading from memory touches no file: what the fuzz target needs.
    bool allowExternalFiles = true;
    // Where what is read only in part goes (an optional extension, a material feature not
    // drawn), one line per kind of problem (scene/Warnings.h); none: not reported.
    Warnings* warnings = nullptr;
};

// Loads a .gltf or .glb file (told apart by content, not by name). Throws Error naming the file
// (and the glTF element, e.g. "meshes[0].primitives[1]") on any problem.
Model loadGltfFile(const std::filesystem::path& path, const GltfOptions& options = {});

// The same from bytes in memory; external URIs resolve against `baseDirectory`.
Model loadGltfMemory(const std::vector<unsigned char>& bytes, const std::string& displayName,
                     const std::filesystem::path& baseDirectory, const GltfOptions& options = {});

}  // namespace manylights
