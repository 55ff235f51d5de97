// Every technique must give forward's image (SPEC.md §2). The final colour is compared as
// unclamped floats, pixel for pixel, with no pixel exempt.
//
// Tolerance: |Δ| ≤ 1e-5 · |forward| + 1e-6 per channel. Both paths run the same vertex
// shader and the same lighting function, and the G-buffer keeps every input in 32-bit
// floats, so on llvmpipe the images are bit-identical. The tolerance (about 80 ulps) leaves
// room for a GPU compiler that contracts multiply-adds differently in two programs; any real
// divergence (a light skipped, a term missing, a G-buffer quantity rounded) is far larger.
#include <gtest/gtest.h>

#include <cmath>

#include "TestSupport.h"
#include "render/Technique.h"

namespace manylights {
namespace {

using test::renderPfm;
using test::scratchDirectory;
using test::writeFile;

void expectSameImage(const Image& reference, const Image& candidate, const std::string& what)
{
    ASSERT_EQ(reference.width, candidate.width);
    ASSERT_EQ(reference.height, candidate.height);
    int failures = 0;
    double worst = 0.0;
    for (std::size_t i = 0; i < reference.rgb.size(); ++i) {
        const double want = reference.rgb[i];
        const double got = candidate.rgb[i];
        const double difference = std::abs(got - want);
        worst = std::max(worst, difference);
        if (!(difference <= 1e-5 * std::abs(want) + 1e-6) && ++failures <= 5) {
            const std::size_t pixel = i / 3;
            ADD_FAILURE() << what << ": pixel (" << pixel % reference.width << ", " << pixel / reference.width
                          << ") channel " << i % 3 << ": forward " << want << ", got " << got;
        }
    }
    EXPECT_EQ(failures, 0) << what << " (largest difference " << worst << ")";
}

struct AgreementCase {
    std::string name;
    std::string scene;  // path, or "" for the default scene
    std::vector<std::string> args;
    // Names the case in test listings instead of dumping its bytes.
    friend void PrintTo(const AgreementCase& c, std::ostream* os) { *os << c.name; }
};

class TechniqueAgreement : public ::testing::TestWithParam<AgreementCase> {};

TEST_P(TechniqueAgreement, EveryTechniqueMatchesForward)
{
    const AgreementCase& c = GetParam();
    const auto dir = scratchDirectory();
    std::vector<std::string> args = c.args;
    args.insert(args.end(), {"--technique", "forward"});
    const Image reference = renderPfm(c.scene, dir / "forward.pfm", args);
    for (const std::string& technique : techniqueNames()) {
        if (technique == "forward")
            continue;
        std::vector<std::string> techniqueArgs = c.args;
        techniqueArgs.insert(techniqueArgs.end(), {"--technique", technique});
        const Image image = renderPfm(c.scene, dir / (technique + ".pfm"), techniqueArgs);
        expectSameImage(reference, image, technique);
    }
}

const std::string kScenes = MANYLIGHTS_SOURCE_DIR "/tests/scenes/";

INSTANTIATE_TEST_SUITE_P(
    Scenes, TechniqueAgreement,
    ::testing::Values(AgreementCase{"default_scene", "", {"--size", "320x180"}},
                      AgreementCase{"default_scene_1024_lights", "", {"--size", "192x108", "--lights", "1024"}},
                      AgreementCase{"spots_points_wide_cone_unbounded", kScenes + "spots_and_points.json",
                                    {"--size", "240x160"}},
                      AgreementCase{"spots_points_300_set_lights", kScenes + "spots_and_points.json",
                                    {"--size", "160x120", "--lights", "300"}},
                      // The camera cases of the light-volume techniques (tests/scenes/*.json say
                      // how each is set up).
                      AgreementCase{"camera_inside_point_light", kScenes + "camera_inside_point_light.json",
                                    {"--size", "160x120"}},
                      AgreementCase{"camera_inside_spot_cone", kScenes + "camera_inside_spot_cone.json",
                                    {"--size", "160x120"}},
                      AgreementCase{"light_cut_by_near_plane", kScenes + "light_cut_by_near_plane.json",
                                    {"--size", "160x120"}},
                      AgreementCase{"light_beyond_far_plane", kScenes + "light_beyond_far_plane.json",
                                    {"--size", "160x120"}},
                      AgreementCase{"spot_cutoff_120", kScenes + "spot_cutoff_120.json", {"--size", "160x120"}},
                      AgreementCase{"unbounded_light", kScenes + "unbounded_light.json", {"--size", "160x120"}},
                      AgreementCase{"small_lights_behind_walls", kScenes + "small_lights_behind_walls.json",
                                    {"--size", "160x90"}},
                      // Shadows (directional, spot maps, cube maps for points and wide spots)
                      // and SSAO: every technique samples the same maps at the same positions.
                      AgreementCase{"shadows_and_ssao", kScenes + "shadows_and_ssao.json",
                                    {"--size", "160x120", "--shadow-lights", "24"}}),
    [](const ::testing::TestParamInfo<AgreementCase>& param) { return param.param.name; });

}  // namespace
}  // namespace manylights
