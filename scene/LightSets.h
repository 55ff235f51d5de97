// Expands a scene's light sets into concrete lights, deterministically for a given seed.
#pragma once

#include <optional>
#include <vector>

#include "scene/Scene.h"

namespace manylights {

// Every light the scene renders: its explicit lights followed by the generated ones.
// `totalSetLights`, when given (the --lights option), replaces the sum of the sets' counts,
// spread over the sets in proportion to their counts (largest remainder, so the sum is exact).
// A set's first k lights are the same whatever its count, so a sweep grows one scene (their
// ranges excepted in a set with range_reference_count, which scales them all by one factor).
std::vector<Light> expandLights(const Scene& scene, std::optional<int> totalSetLights = std::nullopt);

// The lights a command renders (render, bench, view): expandLights(scene, requestedSetLights),
// where `requestedSetLights` is the --lights option. Throws manylights::Error naming the scene
// when it is given and the scene has no light sets to scale.
std::vector<Light> lightsForCommand(const Scene& scene, std::optional<int> requestedSetLights);

// The factor a set with `range_reference_count` referenceCount multiplies its lights' ranges
// by when it generates `count` lights: sqrt(referenceCount / count), so that count · range²
// (the area the lights cover) stays what it is at the reference count.
double rangeScaleFor(int referenceCount, int count);

// The per-set counts that expandLights uses.
std::vector<int> distributeLightCount(const std::vector<LightSet>& sets, int total);

}  // namespace manylights
