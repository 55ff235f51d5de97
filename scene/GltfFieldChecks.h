// The glTF 2.0 schema rules that tinygltf reads past without a word (issue 33): a light's
// `range` of 0 (the schema wants > 0), an object where an array belongs or the reverse
// (`pbrMetallicRoughness: [...]`), a `name` that is a number, an index of −1. tinygltf loads
// such a file with the field left at its default, so the file is still drawn; these checks
// say so, one warning per kind of problem naming the JSON pointer and the field (with
// --strict, an error). Rules: docs/scene-format.md, "Model files".
#pragma once

#include <string_view>

#include "scene/Warnings.h"

namespace manylights {

// Notes in `warnings` every field of the glTF JSON text `json` that breaks the schema in a
// way tinygltf does not report: "/materials/0/pbrMetallicRoughness: pbrMetallicRoughness must
// be an object, got an array; ...". Text that is not JSON is left to tinygltf to report.
void checkGltfFields(std::string_view json, FileWarnings& warnings);

}  // namespace manylights
