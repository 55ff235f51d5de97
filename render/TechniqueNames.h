// The techniques' names, in the order of docs/cli.md. The registry (render/Techniques.h) makes
// each technique by its name and checks, as it compiles, that its table holds these names in
// this order. Apart from it so that what only checks a name, the viewer's script parser, builds
// without the techniques' code (the fuzz target of the command line, tests/fuzz/, builds that
// parser alone).
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace manylights {

inline constexpr std::array<std::string_view, 7> kTechniqueNames = {
    "forward", "deferred", "volumes", "stencil", "tiled-quads", "tiled", "clustered",
};

// kTechniqueNames as strings, for CLI11's IsMember and the messages that list them.
inline const std::vector<std::string>& techniqueNames()
{
    static const std::vector<std::string> names(kTechniqueNames.begin(), kTechniqueNames.end());
    return names;
}

}  // namespace manylights
