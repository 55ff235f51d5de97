#include "render/driver/DriverProfile.h"

#include "gl/Driver.h"

namespace manylights {

namespace {

DriverChoices profileChoices(DriverProfile profile)
{
    if (profile == DriverProfile::Auto)
        profile = gl::isSoftwareRenderer() ? DriverProfile::Software : DriverProfile::Gpu;
    if (profile == DriverProfile::Software)
        return {};
    return {.profile = DriverProfile::Gpu,
            .multipliedSpecularPowers = false,
            .lightTexelsBeforeWindows = false,
            .autoAnisotropy = kHardwareAnisotropy,
            .passTiming = PassTiming::Gpu,
            .lightingStage = LightingStage::Compute,
            .branchOnLightReach = true};
}

}  // namespace

DriverChoices resolveDriverChoices(const DriverOverrides& overrides)
{
    DriverChoices choices = profileChoices(overrides.profile);
    if (overrides.passTiming)
        choices.passTiming = *overrides.passTiming;
    if (overrides.lightingStage)
        choices.lightingStage = *overrides.lightingStage;
    return choices;
}

}  // namespace manylights
