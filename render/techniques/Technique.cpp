#include "render/techniques/Technique.h"

#include "core/EnumNames.h"
#include "render/culling/LightBatches.h"

namespace manylights {

namespace {
constexpr EnumNames<LightingStage, 2> kLightingStages{{
    {LightingStage::Fragment, "fragment"},
    {LightingStage::Compute, "compute"},
}};
}  // namespace

std::string_view lightingStageName(LightingStage stage) { return nameOf(kLightingStages, stage); }
std::optional<LightingStage> parseLightingStage(std::string_view name) { return parseName(kLightingStages, name); }

gl::Defines shaderDefines(const TechniqueOptions& options)
{
    gl::Defines defines = gbufferDefines(options.gbufferLayout);
    addLightBatchDefines(defines);
    if (options.countWork)
        defines.emplace_back("COUNT_WORK", "1");
    if (options.localShadows)
        defines.emplace_back("LOCAL_SHADOWS", "1");
    return defines;
}

}  // namespace manylights
