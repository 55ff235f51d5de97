#include "scene/DisplaySettings.h"

#include "core/EnumNames.h"

namespace manylights {

namespace {
constexpr EnumNames<ToneCurve, 5> kToneCurves{{
    {ToneCurve::None, "none"},
    {ToneCurve::Reinhard, "reinhard"},
    {ToneCurve::Aces, "aces"},
    {ToneCurve::Agx, "agx"},
    {ToneCurve::PbrNeutral, "pbr-neutral"},
}};
constexpr EnumNames<Antialiasing, 2> kAntialiasing{{
    {Antialiasing::None, "none"},
    {Antialiasing::Fxaa, "fxaa"},
}};

}  // namespace

std::optional<ToneCurve> parseToneCurve(std::string_view name) { return parseName(kToneCurves, name); }
std::string_view toneCurveName(ToneCurve curve) { return nameOf(kToneCurves, curve); }
const std::vector<std::string>& toneCurveNames()
{
    static const std::vector<std::string> names = namesOf(kToneCurves);
    return names;
}

std::optional<Antialiasing> parseAntialiasing(std::string_view name) { return parseName(kAntialiasing, name); }
std::string_view antialiasingName(Antialiasing method) { return nameOf(kAntialiasing, method); }
const std::vector<std::string>& antialiasingNames()
{
    static const std::vector<std::string> names = namesOf(kAntialiasing);
    return names;
}

}  // namespace manylights
