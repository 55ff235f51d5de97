#include "scene/LightSets.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <string>

#include "core/Error.h"

namespace manylights {

namespace {

// std::mt19937's output sequence is fixed by the C++ standard, but the distributions are
// not (libstdc++ and libc++ give different numbers), so the conversion to [0, 1) is done
// here: the top 24 bits, scaled exactly into a float.
class Random {
public:
    explicit Random(std::uint32_t seed) : engine_(seed) {}

    float unit() { return static_cast<float>(static_cast<std::uint32_t>(engine_()) >> 8) * 0x1p-24f; }

    float in(const Interval& interval) { return interval.lo + (interval.hi - interval.lo) * unit(); }

private:
    std::mt19937 engine_;
};

// A fully saturated colour (HSV with s = v = 1) for hue in [0, 1).
glm::vec3 hueToRgb(float hue)
{
    const float h = hue * 6.0f;
    // hue just below 1 can round to h = 6 in float; that is red again, as sector 5 gives.
    const float sector = std::min(std::floor(h), 5.0f);
    const float f = h - sector;
    switch (static_cast<int>(sector)) {
    case 0: return {1.0f, f, 0.0f};
    case 1: return {1.0f - f, 1.0f, 0.0f};
    case 2: return {0.0f, 1.0f, f};
    case 3: return {0.0f, 1.0f - f, 1.0f};
    case 4: return {f, 0.0f, 1.0f};
    default: return {1.0f, 0.0f, 1.0f - f};
    }
}

constexpr float kMaxSpotTiltDegrees = 30.0f;

constexpr double kGoldenAngleDegrees = 137.50776405003785;

// Appends `count` lights of `set`. Every light draws the same number of values in the same
// order, so light i depends only on the seed and i: growing the count appends lights and
// never changes the ones before.
void generateSet(const LightSet& set, std::size_t setIndex, int count, std::vector<Light>& out)
{
    Random random(set.seed);
    // The drawn range is scaled after the draw (not the interval before it), so that a light's
    // range at any count is exactly its range at the reference count times this factor.
    float rangeScale = 1.0f;
    if (set.rangeReferenceCount && count > 0)
        rangeScale = static_cast<float>(rangeScaleFor(*set.rangeReferenceCount, count));
    const std::string prefix = "set" + std::to_string(setIndex) + "[";
    for (int i = 0; i < count; ++i) {
        Light light;
        light.type = set.type;
        light.name = prefix + std::to_string(i) + "]";
        light.falloff = Falloff::Range;
        light.castsShadows = set.castsShadows;
        light.position.x = random.in({set.boxMin.x, set.boxMax.x});
        light.position.y = random.in({set.boxMin.y, set.boxMax.y});
        light.position.z = random.in({set.boxMin.z, set.boxMax.z});
        light.range = random.in(set.range) * rangeScale;
        const glm::vec3 colour = hueToRgb(random.unit());
        light.intensity = colour * random.in(set.intensity);
        if (set.type == LightType::Spot) {
            // Straight down, tilted by up to 30 degrees towards a random azimuth: spots that
            // light the floor of a scene whose up is +Y, as light-set scenes are built.
            const float tilt = glm::radians(kMaxSpotTiltDegrees) * random.unit();
            const float azimuth = glm::radians(360.0f) * random.unit();
            light.direction =
                glm::vec3(std::sin(tilt) * std::cos(azimuth), -std::cos(tilt), std::sin(tilt) * std::sin(azimuth));
            light.cutoffDegrees = random.in(set.cutoffDegrees);
            light.exponent = random.in(set.exponent);
        }
        // Spread over the circle by the golden angle, so that no two lights of a set move in
        // lockstep whatever the count; drawn from no random number, so the lights above keep
        // their values.
        if (set.animation)
            light.animation =
                withExtraPhase(*set.animation, static_cast<float>(std::fmod(kGoldenAngleDegrees * i, 360.0)));
        out.push_back(std::move(light));
    }
}

}  // namespace

double rangeScaleFor(int referenceCount, int count)
{
    ML_ASSERT(referenceCount > 0 && count > 0);
    return std::sqrt(static_cast<double>(referenceCount) / static_cast<double>(count));
}

std::vector<int> distributeLightCount(const std::vector<LightSet>& sets, int total)
{
    ML_ASSERT(total >= 0);
    // With no sets there is nowhere to put the lights; the caller decides whether that is
    // an error (the CLI's --lights on a scene without light sets).
    if (sets.empty())
        return {};

    const std::size_t n = sets.size();
    std::vector<int> counts(n, 0);
    std::int64_t sum = 0;
    for (const LightSet& set : sets) {
        ML_ASSERT(set.count >= 0);
        sum += set.count;
    }
    if (sum == 0) {
        // No proportions to follow: spread evenly, the first sets taking the remainder.
        const int each = total / static_cast<int>(n);
        const int extra = total % static_cast<int>(n);
        for (std::size_t i = 0; i < n; ++i)
            counts[i] = each + (static_cast<int>(i) < extra ? 1 : 0);
        return counts;
    }

    // Largest remainder (Hamilton) in exact integer arithmetic: each set gets the floor of its
    // quota total·count/sum, then the sets with the largest fractional parts get one more
    // until the sum is exact. Ties go to the earlier set, so the split is deterministic.
    std::vector<std::int64_t> remainders(n);
    std::int64_t assigned = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const std::int64_t product = static_cast<std::int64_t>(total) * sets[i].count;
        counts[i] = static_cast<int>(product / sum);
        remainders[i] = product % sum;
        assigned += counts[i];
    }
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return remainders[a] > remainders[b]; });
    const std::int64_t leftover = total - assigned;
    ML_ASSERT(leftover >= 0 && leftover <= static_cast<std::int64_t>(n));
    for (std::int64_t k = 0; k < leftover; ++k)
        ++counts[order[static_cast<std::size_t>(k)]];
    return counts;
}

std::vector<Light> expandLights(const Scene& scene, std::optional<int> totalSetLights)
{
    std::vector<int> counts;
    if (totalSetLights) {
        counts = distributeLightCount(scene.lightSets, *totalSetLights);
    } else {
        for (const LightSet& set : scene.lightSets)
            counts.push_back(set.count);
    }

    std::size_t total = scene.lights.size();
    for (int count : counts)
        total += static_cast<std::size_t>(count);
    std::vector<Light> lights;
    lights.reserve(total);
    lights.insert(lights.end(), scene.lights.begin(), scene.lights.end());
    for (std::size_t i = 0; i < counts.size(); ++i)
        generateSet(scene.lightSets[i], i, counts[i], lights);
    return lights;
}

std::vector<Light> lightsForCommand(const Scene& scene, std::optional<int> requestedSetLights)
{
    if (requestedSetLights && scene.lightSets.empty())
        throw Error(scene.source + ": --lights needs a scene with light_sets to scale");
    return expandLights(scene, requestedSetLights);
}

}  // namespace manylights
