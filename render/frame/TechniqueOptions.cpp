#include "render/frame/TechniqueOptions.h"

#include "render/programs/LightBatches.h"

namespace manylights {

gl::Defines shaderDefines(const TechniqueOptions& options)
{
    gl::Defines defines = gbufferDefines(options.gbufferLayout);
    if (options.countWork)
        defines.emplace_back("COUNT_WORK", "1");
    if (options.localShadows)
        defines.emplace_back("LOCAL_SHADOWS", "1");
    return defines;
}

}  // namespace manylights
