// The registry of techniques: their names, and each made by name. Above the rooms of the
// techniques (render/techniques/, render/volumes/), the one place that knows every technique,
// so that no room below includes another's techniques.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "render/TechniqueNames.h"  // techniqueNames()
#include "render/techniques/Technique.h"

namespace manylights {

// nullptr when the name is unknown.
std::unique_ptr<Technique> makeTechnique(std::string_view name, const TechniqueOptions& options = {});
// Which lights the technique's light-count view counts at a pixel, in a few words ("every
// light", "cluster's lights in reach"); empty when the name is unknown.
std::string_view countedLights(std::string_view technique);

}  // namespace manylights
