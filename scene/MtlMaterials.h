// An MTL material library's materials as manylights Materials (docs/scene-format.md, "OBJ and
// MTL"): colours, maps resolved as exporters on other systems write their paths, texture
// options, opacity, and the PBR extension's metallic-roughness keys.
#pragma once

#include <filesystem>
#include <string>

#include <tiny_obj_loader.h>

#include "scene/Scene.h"
#include "scene/Warnings.h"

namespace manylights::detail {

// One material library as it was read: its name (for messages), its directory (for its maps),
// its text (for line numbers) and what was forgiven in it.
struct MtlLibrary {
    std::string displayName;
    std::filesystem::path directory;
    std::string text;
    FileWarnings warnings;
};

// The material `source` of `library`, named "<objName>#<material>". Missing maps are noted in
// the library's warnings; throws Error for a non-finite value or a PBR factor outside [0, 1].
Material convertMaterial(const tinyobj::material_t& source, MtlLibrary& library, const std::string& objName);

}  // namespace manylights::detail
