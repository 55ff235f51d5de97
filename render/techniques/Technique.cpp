#include "render/techniques/Technique.h"

#include "render/culling/LightBatches.h"

namespace manylights {

std::string_view lightingStageName(LightingStage stage)
{
    return stage == LightingStage::Compute ? "compute" : "fragment";
}

std::optional<LightingStage> parseLightingStage(std::string_view name)
{
    for (LightingStage stage : {LightingStage::Fragment, LightingStage::Compute})
        if (lightingStageName(stage) == name)
            return stage;
    return std::nullopt;
}

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
