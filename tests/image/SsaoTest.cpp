// Screen-space ambient occlusion (docs/shadows.md): a box standing on a floor, lit by the
// ambient term only, so every pixel's colour is kd · ambient · ao.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "TestSupport.h"
#include "render/Techniques.h"
#include "render/techniques/Technique.h"

namespace manylights {
// Every render here uses the exact seed G-buffer layout: the expected values are docs/lighting.md
// evaluated by hand, and the compact layout's 8-bit kd (0.5 stored as 128/255) would move
// them by more than the analytic tolerance (its own bound is TechniqueAgreementTest's).
namespace {

using test::renderPfm;
using test::scratchDirectory;
using test::writeFile;

const char* kBoxOnFloor = R"({
    "camera": {"eye": [4, 5, 6], "look_at": [0, 0.5, 0], "up": [0, 1, 0], "fov_y": 50, "near": 0.1, "far": 100},
    "ambient": [0.2, 0.2, 0.2],
    "ssao": {"radius": 0.5, "strength": 1, "enabled": ENABLED},
    "materials": {"grey": {"diffuse": [0.5, 0.5, 0.5]}},
    "objects": [
        {"mesh": {"primitive": "plane", "size": [30, 30]}, "material": "grey"},
        {"mesh": {"primitive": "box", "size": [2, 2, 2]}, "material": "grey", "transform": {"translate": [0, 1, 0]}}]})";
const std::string kSize = "192x144";

std::string boxOnFloor(bool enabled)
{
    std::string scene = kBoxOnFloor;
    scene.replace(scene.find("ENABLED"), 7, enabled ? "true" : "false");
    return scene;
}

struct Views {
    Image occlusion;
    Image position;
    Image normal;
    bool covered(int x, int y) const { return test::holdsSurface(normal, x, y); }
    bool floor(int x, int y) const { return covered(x, y) && std::abs(position.pixel(x, y)[1]) < 1e-3f; }
};

Views renderViews(const std::filesystem::path& scene, const std::filesystem::path& dir)
{
    Views v;
    v.occlusion = renderPfm(scene.string(), dir / "ssao.pfm", {"--gbuffer", "seed", "--size", kSize, "--view", "ssao"});
    v.position =
        renderPfm(scene.string(), dir / "position.pfm", {"--gbuffer", "seed", "--size", kSize, "--view", "position"});
    v.normal =
        renderPfm(scene.string(), dir / "normal.pfm", {"--gbuffer", "seed", "--size", kSize, "--view", "normal"});
    return v;
}

TEST(Ssao, DarkensTheInnerCornerAndLeavesOpenFloorUnoccluded)
{
    const auto dir = scratchDirectory();
    writeFile(dir / "scene.json", boxOnFloor(true));
    const Views v = renderViews(dir / "scene.json", dir);

    // The inner corner: floor pixels within 0.05 of the box's walls. There about half of the
    // hemisphere (everything on the wall's side) is inside the box, so the raw factor is near
    // 1 − ½ = 0.5; the 4x4 blur mixes in pixels up to two pixels (about 0.1 here) farther out,
    // where fewer kernel points (0.05 to 0.5 long) reach the wall. 0.95 leaves room for that
    // mixing and still fails when occlusion is missing (1) or barely there.
    int corner = 0;
    int open = 0;
    constexpr int kNeighbourhood = 12;  // pixels: more than the radius (≈ 9 pixels here) plus the blur's 2
    for (int y = 0; y < v.occlusion.height; ++y)
        for (int x = 0; x < v.occlusion.width; ++x) {
            if (!v.floor(x, y))
                continue;
            const float* p = v.position.pixel(x, y);
            const double outside = std::hypot(std::max(std::abs(p[0]) - 1.0, 0.0), std::max(std::abs(p[2]) - 1.0, 0.0));
            const float ao = v.occlusion.pixel(x, y)[0];
            if (outside < 0.05) {
                ++corner;
                EXPECT_LT(ao, 0.95f) << "corner pixel (" << x << ", " << y << ")";
            }
            // Open floor: every pixel its kernel and blur can reach shows the floor. Each
            // kernel point lies at least 10° above the plane, and the occluder's depth is the
            // floor's own plane along the point's view ray (shaders/ssao.comp), so the floor
            // never occludes itself: the factor is 1 up to float rounding, far below the
            // test's bias of 0.02 · radius.
            bool onlyFloorAround = true;
            for (int dy = -kNeighbourhood; dy <= kNeighbourhood && onlyFloorAround; ++dy)
                for (int dx = -kNeighbourhood; dx <= kNeighbourhood && onlyFloorAround; ++dx) {
                    const int nx = x + dx;
                    const int ny = y + dy;
                    onlyFloorAround =
                        nx >= 0 && ny >= 0 && nx < v.occlusion.width && ny < v.occlusion.height && v.floor(nx, ny);
                }
            if (onlyFloorAround) {
                ++open;
                EXPECT_NEAR(ao, 1.0f, 1e-6f) << "open floor pixel (" << x << ", " << y << ")";
            }
        }
    EXPECT_GT(corner, 30);
    EXPECT_GT(open, 5000);
}

TEST(Ssao, MultipliesTheAmbientTermInEveryTechnique)
{
    const auto dir = scratchDirectory();
    writeFile(dir / "scene.json", boxOnFloor(true));
    const Views v = renderViews(dir / "scene.json", dir);
    int darkened = 0;
    for (const std::string& technique : techniqueNames()) {
        const Image colour = renderPfm((dir / "scene.json").string(), dir / (technique + ".pfm"),
                                       {"--gbuffer", "seed", "--size", kSize, "--technique", technique});
        int failures = 0;
        for (int y = 0; y < colour.height; ++y)
            for (int x = 0; x < colour.width; ++x) {
                if (!v.covered(x, y))
                    continue;
                // color = ke + ambient ⊙ kd · ao, in the shader's float order.
                const float ao = v.occlusion.pixel(x, y)[0];
                const float want = 0.2f * 0.5f * ao;
                if (colour.pixel(x, y)[0] != want && ++failures <= 3)
                    ADD_FAILURE() << technique << " pixel (" << x << ", " << y << "): got " << colour.pixel(x, y)[0]
                                  << ", expected " << want;
                if (technique == "forward" && ao < 0.95f)
                    ++darkened;
            }
        EXPECT_EQ(failures, 0) << technique;
    }
    EXPECT_GT(darkened, 30);
}

TEST(Ssao, OffUnlessTheSceneEnablesIt)
{
    // docs/lighting.md has no occlusion term: with "enabled": false the image is kd · ambient exactly.
    const auto dir = scratchDirectory();
    writeFile(dir / "scene.json", boxOnFloor(false));
    const Image colour =
        renderPfm((dir / "scene.json").string(), dir / "final.pfm", {"--gbuffer", "seed", "--size", kSize});
    const Image normal = renderPfm((dir / "scene.json").string(), dir / "normal.pfm",
                                   {"--gbuffer", "seed", "--size", kSize, "--view", "normal"});
    int checked = 0;
    for (int y = 0; y < colour.height; ++y)
        for (int x = 0; x < colour.width; ++x) {
            if (!test::holdsSurface(normal, x, y))
                continue;
            ++checked;
            ASSERT_EQ(colour.pixel(x, y)[0], 0.2f * 0.5f) << "pixel (" << x << ", " << y << ")";
        }
    EXPECT_GT(checked, 10000);
}

// SSAO needs the G-buffer before the technique runs; a G-buffer technique then uses the same
// one: the frame has one geometry pass, not two (GBuffer::fill within a frame).
TEST(Ssao, TheGBufferIsFilledOncePerFrame)
{
    const auto dir = scratchDirectory();
    writeFile(dir / "scene.json", boxOnFloor(true));
    for (const std::string technique : {"deferred", "clustered"}) {
        const std::filesystem::path stats = dir / (technique + ".json");
        renderPfm((dir / "scene.json").string(), dir / "final.pfm",
                  {"--size", "64x48", "--technique", technique, "--frames", "2", "--stats", stats.string()});
        std::ifstream in(stats);
        const nlohmann::json measured = nlohmann::json::parse(in);
        std::vector<std::string> passes;
        for (const nlohmann::json& pass : measured["passes"])
            passes.push_back(pass["name"].get<std::string>());
        EXPECT_EQ(std::count(passes.begin(), passes.end(), "geometry"), 1) << technique;
        EXPECT_EQ(std::count(passes.begin(), passes.end(), "ssao"), 1) << technique;
    }
}

}  // namespace
}  // namespace manylights
