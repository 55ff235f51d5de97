// The dynamic surface of revolution (positions and normals computed in the vertex shader from
// the uvs and the frame time, shaders/lib/revolution.glsl) against the same surface built on
// the CPU at that time (scene/Revolution.cpp), through the position and normal views.
//
// Tolerance: 2e-4 per channel. Both are the same grid with the same uvs, rasterised the same
// way; only the vertex values differ, by the float rounding of GLSL's sin/cos against the C
// library's (a few ulps of values of order 1; llvmpipe's sin/cos are accurate to ~1e-6).
// A surface at another time differs by up to 2 · amplitude (0.3) in position, far above it.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "TestSupport.h"

namespace manylights {
namespace {

using test::renderPfm;
using test::scratchDirectory;
using test::writeFile;

std::string revolutionScene(const std::string& mesh)
{
    return R"json({
  "camera": {"eye": [0, 1.2, 3], "look_at": [0, 0.7, 0], "fov_y": 45},
  "ambient": [0.2, 0.2, 0.2],
  "objects": [ {"mesh": )json" +
           mesh + R"json(, "transform": {"rotate": [0, 20, 0]}} ]
})json";
}

const char* const kProfile = R"("radius": 0.5, "height": 1.4, "amplitude": 0.15, "waves": 1.5, "speed": 0.4)";

double largestDifference(const Image& a, const Image& b)
{
    double worst = 0.0;
    for (std::size_t i = 0; i < a.rgb.size(); ++i)
        worst = std::max(worst, static_cast<double>(std::abs(a.rgb[i] - b.rgb[i])));
    return worst;
}

TEST(SurfaceOfRevolution, VertexShaderMatchesTheCpuSurface)
{
    const auto dir = scratchDirectory();
    const std::string time = "1.3";
    writeFile(dir / "dynamic.json",
              revolutionScene(std::string(R"({"primitive": "revolution", "dynamic": true, )") + kProfile + "}"));
    writeFile(dir / "frozen.json",
              revolutionScene(std::string(R"({"primitive": "revolution", "time": )") + time + ", " + kProfile + "}"));
    writeFile(dir / "frozen_at_0.json",
              revolutionScene(std::string(R"({"primitive": "revolution", "time": 0, )") + kProfile + "}"));
    for (const char* view : {"position", "normal"}) {
        const std::vector<std::string> args{"--size", "96x96", "--view", view};
        std::vector<std::string> atTime = args;
        atTime.insert(atTime.end(), {"--time", time});
        const Image gpu = renderPfm((dir / "dynamic.json").string(), dir / "gpu.pfm", atTime);
        // The frozen surface does not depend on --time; rendered at the same time anyway.
        const Image cpu = renderPfm((dir / "frozen.json").string(), dir / "cpu.pfm", atTime);
        const Image other = renderPfm((dir / "frozen_at_0.json").string(), dir / "other.pfm", atTime);
        int covered = 0;
        for (std::size_t i = 0; i < cpu.rgb.size(); i += 3)
            covered += cpu.rgb[i] != 0.0f || cpu.rgb[i + 1] != 0.0f || cpu.rgb[i + 2] != 0.0f;
        EXPECT_GT(covered, 96 * 96 / 8) << view << ": the surface should fill much of the image";
        EXPECT_LE(largestDifference(gpu, cpu), 2e-4) << view;
        // The check can fail: the surface at another time is far outside the tolerance.
        EXPECT_GT(largestDifference(gpu, other), 0.05) << view;
    }
}

}  // namespace
}  // namespace manylights
