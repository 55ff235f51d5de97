#include "render/programs/LightBatches.h"

#include <algorithm>
#include <string>

#include "core/Error.h"
#include "gl/Driver.h"
#include "render/programs/Locations.h"

namespace manylights {

// A pixel's worst case: a batch of lights with their bit-mask walk, and the directional and
// every shadowed local light's lookup.
static_assert(kLightsPerBatch + 2 * (kLightsPerBatch / 32) + 64 + kShadowLookupBudget <= kMaxLoopIterations);

std::vector<LightBatch> lightBatches(std::uint32_t lightCount, std::uint32_t perBatch)
{
    ML_ASSERT(perBatch > 0 && perBatch <= kLightsPerBatch);
    std::vector<LightBatch> batches;
    std::uint32_t first = 0;
    do {
        const std::uint32_t end = first + std::min(perBatch, lightCount - first);
        batches.push_back({first, end});
        first = end;
    } while (first < lightCount);
    return batches;
}

void setLightBatch(const gl::Program& program, const LightBatch& batch)
{
    program.set(locations::LIGHT_BATCH_LOCATION, glm::uvec2(batch.first, batch.end));
}

bool fitsOneLightWindow(const std::vector<LightBatch>& batches)
{
    return batches.size() == 1 && batches.front().size() <= kLightsPerWindow;
}

bool lightWindowsSupported()
{
    return static_cast<std::size_t>(gl::queryInteger(GL_MAX_UNIFORM_BLOCK_SIZE)) >= kLightWindowBytes;
}

bool lightTexelsSupported(std::size_t lightCount)
{
    const auto units = static_cast<unsigned>(
        std::min(gl::queryInteger(GL_MAX_TEXTURE_IMAGE_UNITS), gl::queryInteger(GL_MAX_COMPUTE_TEXTURE_IMAGE_UNITS)));
    const auto maxTexels = static_cast<std::size_t>(gl::queryInteger(GL_MAX_TEXTURE_BUFFER_SIZE));
    return units > kLightTexelsUnit && lightCount * kTexelsPerLight <= maxTexels;
}

}  // namespace manylights
