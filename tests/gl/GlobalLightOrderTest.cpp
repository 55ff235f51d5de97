// The global list's sort (shaders/global_light_order.comp, render/culling/ClusterLists.h): the
// candidates come from the counting run's atomics in any order, and must come out in the
// lights' order with each light's record beside it, or not at all when they are more than the
// list holds; the list's length after its last possible entry. The pass alone, on candidates shuffled here: on llvmpipe
// the atomics hand out the slots nearly in the lights' order, so an image cannot show an unsorted list.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "ClusterListStatus.h"
#include "GlContextTest.h"
#include "gl/Buffer.h"
#include "gl/Program.h"
#include "render/culling/ClusterLists.h"
#include "render/programs/Bindings.h"
#include "render/scene/SceneLights.h"

namespace manylights {
namespace {

class GlobalLightOrderTest : public GlContextTest {};

// ClusterListStatus (tests/gl/ClusterListStatus.h): its 15th uint counts the candidates.
constexpr std::size_t kCandidatesIndex = 14;
constexpr std::uint32_t kUnwritten = 0xdeadbeefu;

TEST_F(GlobalLightOrderTest, SortsTheCandidatesIntoTheLightsOrderWithTheirRecords)
{
    const gl::Program program("global light order test", {{GL_COMPUTE_SHADER, "global_light_order.comp"}},
                              {{"GLOBAL_LIGHT_CAPACITY", std::to_string(kGlobalLightCapacity)}});
    constexpr std::uint32_t kLights = 20000;
    std::vector<GpuLight> lights(kLights);
    for (std::uint32_t i = 0; i < kLights; ++i) {
        const auto f = static_cast<float>(i);
        lights[i] = {{f, 2 * f, 3 * f, f + 0.5f}, {f, 1, 2, 3}, {4, f, 5, 6}, {7, 8, f, -2}};
    }
    gl::Buffer lightBuffer("test lights", lights.size() * sizeof(GpuLight), lights.data(), 0);
    std::mt19937 random(29);
    // Up to the capacity, and one over it, which must leave the list as it was.
    for (const std::uint32_t count : {1u, 300u, kGlobalLightCapacity, kGlobalLightCapacity + 1}) {
        std::vector<std::uint32_t> all(kLights);
        std::iota(all.begin(), all.end(), 0u);
        std::shuffle(all.begin(), all.end(), random);
        std::vector<std::uint32_t> candidates(all.begin(), all.begin() + count);
        std::vector<std::uint32_t> status(test::kClusterListStatusUints, 0u);
        status[kCandidatesIndex] = count;
        // The counting run writes at most the capacity's worth.
        candidates.resize(std::min(count, kGlobalLightCapacity));
        gl::Buffer statusBuffer("test status", status.size() * sizeof(std::uint32_t), status.data(), 0);
        gl::Buffer candidateBuffer("test candidates", candidates.size() * sizeof(std::uint32_t), candidates.data(), 0);
        const std::vector<std::uint32_t> unwritten(kGlobalLightCapacity * (1 + sizeof(GpuLight) / 4), kUnwritten);
        gl::Buffer sorted("test global lights", (kGlobalLightCapacity + 1) * sizeof(std::uint32_t), unwritten.data(),
                          0);
        gl::Buffer records("test global records", kGlobalLightCapacity * sizeof(GpuLight), unwritten.data(), 0);
        lightBuffer.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::LIGHTS_BUFFER_BINDING);
        statusBuffer.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::CLUSTER_LIST_STATUS_BUFFER_BINDING);
        candidateBuffer.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::GLOBAL_LIGHT_CANDIDATES_BUFFER_BINDING);
        sorted.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::GLOBAL_LIGHTS_BUFFER_BINDING);
        records.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::GLOBAL_LIGHT_RECORDS_BUFFER_BINDING);
        program.use();
        glDispatchCompute(kGlobalLightCapacity / 64, 1, 1);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);

        std::vector<std::uint32_t> order(kGlobalLightCapacity + 1);
        sorted.read(0, order.size() * sizeof(std::uint32_t), order.data());
        std::vector<GpuLight> recordsRead(kGlobalLightCapacity);
        records.read(0, recordsRead.size() * sizeof(GpuLight), recordsRead.data());
        const std::uint32_t listed = count <= kGlobalLightCapacity ? count : 0;
        std::vector<std::uint32_t> expected(candidates.begin(), candidates.begin() + listed);
        std::sort(expected.begin(), expected.end());
        EXPECT_EQ(order[kGlobalLightCapacity], listed) << count << " candidates: the list's length after it";
        for (std::uint32_t k = 0; k < kGlobalLightCapacity; ++k) {
            if (k < listed) {
                ASSERT_EQ(order[k], expected[k]) << count << " candidates, entry " << k;
                const GpuLight& want = lights[expected[k]];
                ASSERT_EQ(recordsRead[k].positionRadius, want.positionRadius) << count << " candidates, entry " << k;
                ASSERT_EQ(recordsRead[k].intensityExponent, want.intensityExponent) << k;
                ASSERT_EQ(recordsRead[k].attenuation, want.attenuation) << k;
                ASSERT_EQ(recordsRead[k].spotAxisCosCutoff, want.spotAxisCosCutoff) << k;
            } else {
                ASSERT_EQ(order[k], kUnwritten) << count << " candidates, entry " << k << " written";
            }
        }
    }
}

}  // namespace
}  // namespace manylights
