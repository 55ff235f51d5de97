// The scene file's lights and light sets (scene/SceneFileLoader.h has the index).
#include "scene/SceneFileLoader.h"

namespace manylights::scene_file {

using namespace scene_json;  // the wording of messages (scene/JsonText.h)

LightType Loader::lightType(const Node& node, const char* what) const
{
    const std::string type = string(node);
    if (type == "point")
        return LightType::Point;
    if (type == "spot")
        return LightType::Spot;
    std::string hint;
    if (const auto guess = closest(type, {"point", "spot"}))
        hint = " (did you mean " + quote(*guess) + "?)";
    fail(node, std::string(what) + " type must be 'point' or 'spot', got " + quote(type) + hint);
}

void Loader::rejectSpotKeys(const Node& node, Keys spotKeys, const char* what) const
{
    for (std::string_view key : spotKeys)
        if (const auto found = member(node, key))
            fail(*found, quote(key) + " applies only to spot " + what + " (this one has type 'point')");
}

Light Loader::readLight(const Node& node, std::size_t index) const
{
    expectObject(node);
    Light light;
    light.type = lightType(required(node, "type"), "light");
    if (light.type == LightType::Point) {
        rejectSpotKeys(node, {"direction", "cutoff", "exponent"}, "lights");
        expectKeys(node, {"type", "name", "pos", "intensity", "attenuation", "range", "animation", "casts_shadows"});
    } else {
        expectKeys(node, {"type", "name", "pos", "intensity", "attenuation", "range", "direction", "cutoff", "exponent",
                          "animation", "casts_shadows"});
    }
    if (const auto animation = member(node, "animation"))
        light.animation = readLightAnimation(*animation);
    if (const auto name = member(node, "name"))
        light.name = string(*name);
    else
        light.name = "lights[" + std::to_string(index) + "]";
    light.position = vec3(required(node, "pos"));
    light.intensity = colour(required(node, "intensity"));
    if (const auto castsShadows = member(node, "casts_shadows"))
        light.castsShadows = boolean(*castsShadows);

    const auto attenuation = member(node, "attenuation");
    const auto range = member(node, "range");
    if (attenuation && range)
        fail(node, "has both 'attenuation' and 'range'; give exactly one");
    if (!attenuation && !range)
        fail(node, "needs a falloff: give exactly one of 'attenuation' or 'range'");
    if (attenuation) {
        light.falloff = Falloff::Classic;
        light.attenuation = readAttenuation(*attenuation);
    } else {
        light.falloff = Falloff::Range;
        light.range = positive(*range);
    }

    if (light.type == LightType::Spot) {
        light.direction = direction(required(node, "direction"));
        light.cutoffDegrees = cutoff(required(node, "cutoff"));
        light.exponent = 0.0f;
        if (const auto exponent = member(node, "exponent"))
            light.exponent = nonNegative(*exponent);
    }
    return light;
}

ClassicAttenuation Loader::readAttenuation(const Node& node) const
{
    expectKeys(node, {"constant", "linear", "quadratic"});
    ClassicAttenuation k;  // OpenGL's defaults: constant 1, linear 0, quadratic 0
    if (const auto c = member(node, "constant"))
        k.constant = nonNegative(*c);
    if (const auto b = member(node, "linear"))
        k.linear = nonNegative(*b);
    if (const auto a = member(node, "quadratic"))
        k.quadratic = nonNegative(*a);
    if (k.constant == 0.0f && k.linear == 0.0f && k.quadratic == 0.0f)
        fail(node, "constant, linear and quadratic must not all be zero");
    return k;
}

void Loader::readLightSets(const Node& node)
{
    expectArray(node, kMaxLightSets, "light sets");
    std::int64_t total = 0;
    for (std::size_t i = 0; i < node.json->size(); ++i) {
        const Node setNode = element(node, i);
        scene_.lightSets.push_back(readLightSet(setNode));
        total += scene_.lightSets.back().count;
        if (total > kMaxSetLights)
            fail(required(setNode, "count"), "the light sets' counts add up to " + std::to_string(total) +
                                                 ", more than " + std::to_string(kMaxSetLights));
    }
}

LightSet Loader::readLightSet(const Node& node) const
{
    expectObject(node);
    LightSet set;
    if (const auto type = member(node, "type"))
        set.type = lightType(*type, "light set");
    if (set.type == LightType::Point) {
        rejectSpotKeys(node, {"cutoff", "exponent"}, "light sets");
        expectKeys(node, {"count", "seed", "type", "min", "max", "range", "range_reference_count", "intensity",
                          "animation", "casts_shadows"});
    } else {
        expectKeys(node, {"count", "seed", "type", "min", "max", "range", "range_reference_count", "intensity",
                          "cutoff", "exponent", "animation", "casts_shadows"});
    }
    if (const auto animation = member(node, "animation"))
        set.animation = readLightAnimation(*animation);
    set.count = static_cast<int>(integer(required(node, "count"), 0, kMaxSetLights));
    if (const auto seed = member(node, "seed"))
        set.seed = static_cast<std::uint32_t>(integer(*seed, 0, 4294967295));
    set.boxMin = vec3(required(node, "min"));
    const Node maxNode = required(node, "max");
    set.boxMax = vec3(maxNode);
    for (int axis = 0; axis < 3; ++axis) {
        if (set.boxMin[axis] > set.boxMax[axis]) {
            const char* const names[] = {"x", "y", "z"};
            fail(element(maxNode, static_cast<std::size_t>(axis)),
                 std::string("must be >= min on every axis, got max.") + names[axis] + " " +
                     formatFloat(set.boxMax[axis]) + " < min." + names[axis] + " " + formatFloat(set.boxMin[axis]));
        }
    }
    set.range = interval(required(node, "range"), &Reader::positive);
    if (const auto reference = member(node, "range_reference_count"))
        set.rangeReferenceCount = static_cast<int>(integer(*reference, 1, kMaxSetLights));
    set.intensity = interval(required(node, "intensity"), &Reader::nonNegative);
    if (const auto castsShadows = member(node, "casts_shadows"))
        set.castsShadows = boolean(*castsShadows);
    if (set.type == LightType::Spot) {
        if (const auto cutoffNode = member(node, "cutoff"))
            set.cutoffDegrees = numberOrInterval(*cutoffNode, &Reader::cutoff);
        if (const auto exponent = member(node, "exponent"))
            set.exponent = numberOrInterval(*exponent, &Reader::nonNegative);
    }
    return set;
}

LightAnimation Loader::readLightAnimation(const Node& node) const
{
    const auto [kind, settings] = animationKind(node, {"orbit", "drift"});
    if (kind == "orbit") {
        expectKeys(settings, {"radius", "speed", "phase"});
        OrbitAnimation orbit;
        orbit.radius = optionalNumber(settings, "radius", orbit.radius, &Reader::nonNegative);
        orbit.degreesPerSecond = optionalNumber(settings, "speed", orbit.degreesPerSecond, &Reader::number);
        orbit.phaseDegrees = optionalNumber(settings, "phase", orbit.phaseDegrees, &Reader::number);
        return orbit;
    }
    expectKeys(settings, {"amplitude", "period", "phase"});
    DriftAnimation drift;
    if (const auto amplitude = member(settings, "amplitude"))
        drift.amplitude = vec3(*amplitude, &Reader::nonNegative);
    if (const auto period = member(settings, "period"))
        drift.period = vec3(*period, &Reader::positive);
    drift.phaseDegrees = optionalNumber(settings, "phase", drift.phaseDegrees, &Reader::number);
    return drift;
}

}  // namespace manylights::scene_file
