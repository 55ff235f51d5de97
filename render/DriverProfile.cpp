#include "render/DriverProfile.h"

#include "gl/Driver.h"
#include "render/scene/TextureCache.h"

namespace manylights {

std::string_view driverProfileName(DriverProfile profile)
{
    switch (profile) {
    case DriverProfile::Auto: return "auto";
    case DriverProfile::Software: return "software";
    case DriverProfile::Gpu: return "gpu";
    }
    return "auto";
}

std::optional<DriverProfile> parseDriverProfile(std::string_view name)
{
    for (DriverProfile profile : {DriverProfile::Auto, DriverProfile::Software, DriverProfile::Gpu})
        if (name == driverProfileName(profile))
            return profile;
    return std::nullopt;
}

DriverChoices driverChoices(DriverProfile profile)
{
    if (profile == DriverProfile::Auto)
        profile = gl::isSoftwareRenderer() ? DriverProfile::Software : DriverProfile::Gpu;
    if (profile == DriverProfile::Software)
        return {};
    return {.profile = DriverProfile::Gpu,
            .multipliedSpecularPowers = false,
            .lightTexelsBeforeWindows = false,
            .autoAnisotropy = kHardwareAnisotropy,
            .finishAroundPasses = false,
            .computeLighting = true,
            .branchOnLightReach = true};
}

}  // namespace manylights
