// The registry of techniques: the one place that knows every technique, so that the base
// class (render/techniques/Technique.h) includes none of them.
#include "render/techniques/ClusteredTechnique.h"
#include "render/techniques/DeferredTechnique.h"
#include "render/techniques/ForwardTechnique.h"
#include "render/techniques/Technique.h"
#include "render/techniques/TiledQuadsTechnique.h"
#include "render/techniques/TiledTechnique.h"
#include "render/volumes/VolumeTechniques.h"

namespace manylights {

namespace {

// Every technique, in the order of the docs: the one list the names and the factory come from,
// so a technique cannot be named without being made or made without being named.
struct TechniqueEntry {
    std::string_view name;
    std::unique_ptr<Technique> (*make)(const TechniqueOptions& options);
};

template <typename T>
std::unique_ptr<Technique> make(const TechniqueOptions& options)
{
    return std::make_unique<T>(options);
}

constexpr TechniqueEntry kTechniques[] = {
    {"forward", make<ForwardTechnique>},        {"deferred", make<DeferredTechnique>},
    {"volumes", make<VolumesTechnique>},        {"stencil", make<StencilTechnique>},
    {"tiled-quads", make<TiledQuadsTechnique>}, {"tiled", make<TiledTechnique>},
    {"clustered", make<ClusteredTechnique>},
};

}  // namespace

const std::vector<std::string>& techniqueNames()
{
    static const std::vector<std::string> names = [] {
        std::vector<std::string> result;
        for (const TechniqueEntry& entry : kTechniques)
            result.emplace_back(entry.name);
        return result;
    }();
    return names;
}

std::unique_ptr<Technique> makeTechnique(std::string_view name, const TechniqueOptions& options)
{
    for (const TechniqueEntry& entry : kTechniques)
        if (entry.name == name)
            return entry.make(options);
    return nullptr;
}

}  // namespace manylights
