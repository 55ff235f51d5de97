#include "render/Techniques.h"

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
// so a technique cannot be named without being made or made without being named. With each, the
// lights its light-count view counts at a pixel (its shaders' recordLightEvaluations), which the
// view's legend names (render/HeatMapLegend.h); 26 characters at most, for the legend.
struct TechniqueEntry {
    std::string_view name;
    std::unique_ptr<Technique> (*make)(const TechniqueOptions& options);
    std::string_view countedLights;
};

template <typename T>
std::unique_ptr<Technique> make(const TechniqueOptions& options)
{
    return std::make_unique<T>(options);
}

constexpr TechniqueEntry kTechniques[] = {
    {"forward", make<ForwardTechnique>, "every light"},
    {"deferred", make<DeferredTechnique>, "every light"},
    // Each volume whose back faces lie behind the pixel's surface (in reach of it or not).
    {"volumes", make<VolumesTechnique>, "volumes behind its surface"},
    // Each volume the stencil test finds around the pixel's surface.
    {"stencil", make<StencilTechnique>, "volumes around its surface"},
    {"tiled-quads", make<TiledQuadsTechnique>, "every light of its tile"},
    // The list's lights that pass the reach test (the others are tested, not shaded).
    {"tiled", make<TiledTechnique>, "tile's lights in reach"},
    {"clustered", make<ClusteredTechnique>, "cluster's lights in reach"},
};

// The table holds the names render/TechniqueNames.h gives, in its order.
constexpr bool namesAreTheTechniqueNames()
{
    if (std::size(kTechniques) != kTechniqueNames.size())
        return false;
    for (std::size_t i = 0; i < kTechniqueNames.size(); ++i)
        if (kTechniques[i].name != kTechniqueNames[i])
            return false;
    return true;
}
static_assert(namesAreTheTechniqueNames(),
              "kTechniques and kTechniqueNames name the same techniques in the same order");

}  // namespace

std::unique_ptr<Technique> makeTechnique(std::string_view name, const TechniqueOptions& options)
{
    for (const TechniqueEntry& entry : kTechniques)
        if (entry.name == name)
            return entry.make(options);
    return nullptr;
}

std::string_view countedLights(std::string_view technique)
{
    for (const TechniqueEntry& entry : kTechniques)
        if (entry.name == technique)
            return entry.countedLights;
    return {};
}

}  // namespace manylights
