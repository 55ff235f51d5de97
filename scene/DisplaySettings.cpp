#include "scene/DisplaySettings.h"

#include <array>
#include <utility>

namespace manylights {

namespace {
constexpr std::array<std::pair<ToneCurve, std::string_view>, 4> kToneCurves{{
    {ToneCurve::None, "none"},
    {ToneCurve::Reinhard, "reinhard"},
    {ToneCurve::Aces, "aces"},
    {ToneCurve::Agx, "agx"},
}};
constexpr std::array<std::pair<Antialiasing, std::string_view>, 2> kAntialiasing{{
    {Antialiasing::None, "none"},
    {Antialiasing::Fxaa, "fxaa"},
}};

template <typename Enum, std::size_t N>
std::optional<Enum> parseName(const std::array<std::pair<Enum, std::string_view>, N>& table, std::string_view name)
{
    for (const auto& [value, text] : table)
        if (text == name)
            return value;
    return std::nullopt;
}

template <typename Enum, std::size_t N>
std::string_view nameOf(const std::array<std::pair<Enum, std::string_view>, N>& table, Enum value)
{
    for (const auto& [entry, text] : table)
        if (entry == value)
            return text;
    return "?";
}

template <typename Enum, std::size_t N>
std::vector<std::string> namesOf(const std::array<std::pair<Enum, std::string_view>, N>& table)
{
    std::vector<std::string> names;
    for (const auto& entry : table)
        names.emplace_back(entry.second);
    return names;
}
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
