// The GPU prefix sum of the light lists (render/culling/GpuScan.h): exact against the CPU's at the sizes
// where its levels change (one block, a block and one, two levels, three levels), with the total
// written where asked.
#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include "OnePlaneFrameTest.h"
#include "render/culling/GpuScan.h"

namespace manylights {
namespace {

class GpuScanTest : public OnePlaneFrameTest {};

TEST_F(GpuScanTest, EqualsTheSumOfEverythingBeforeAtEveryLevel)
{
    static_assert(kScanBlock == 256, "the sizes below straddle the levels of 256-element blocks");
    GpuScan scan;
    std::mt19937 random(29);
    for (const std::uint32_t count : {1u, 255u, 256u, 257u, 65536u, 65537u, 1000003u}) {
        std::vector<std::uint32_t> values(count);
        // Up to 4,000 each: the total stays far below 2^32 at a million elements.
        for (std::uint32_t& value : values)
            value = static_cast<std::uint32_t>(random() % 4001);
        gl::Buffer data("scan test data", values.size() * sizeof(std::uint32_t), values.data(), 0);
        const std::uint32_t sentinel[5] = {7, 7, 7, 7, 7};
        gl::Buffer totals("scan test totals", sizeof sentinel, sentinel, 0);
        profiler_.beginFrame();
        {
            FramePasses passes(gpuScene_, targets_, profiler_);
            scan.run(passes, "scan", data, count, std::pair{&totals, 3u});
            passes.finish();
        }
        profiler_.endFrame();
        std::vector<std::uint32_t> scanned(count);
        data.read(0, scanned.size() * sizeof(std::uint32_t), scanned.data());
        std::vector<std::uint32_t> expected(count);
        std::exclusive_scan(values.begin(), values.end(), expected.begin(), 0u);
        EXPECT_EQ(scanned, expected) << count << " elements";
        std::uint32_t written[5] = {};
        totals.read(0, sizeof written, written);
        EXPECT_EQ(written[3], std::accumulate(values.begin(), values.end(), 0u)) << count << " elements";
        // Nothing else of the totals buffer is touched.
        EXPECT_EQ(written[2], 7u);
        EXPECT_EQ(written[4], 7u);
    }
}

}  // namespace
}  // namespace manylights
