// Every technique must give forward's image (docs/lighting.md). The final colour is compared as
// unclamped floats, pixel for pixel, with no pixel exempt.
//
// Seed G-buffer layout (exact): |Δ| ≤ 1e-5 · |forward| + 1e-6 per channel. Both paths run the
// same vertex shader and the same lighting function, and the seed G-buffer keeps every input in
// 32-bit floats, so on llvmpipe the images are bit-identical. The tolerance (about 80 ulps)
// leaves room for a GPU compiler that contracts multiply-adds differently in two programs; any
// real divergence (a light skipped, a term missing, a G-buffer quantity rounded) is far larger.
// Every case runs with the seed layout for that reason. One more difference is the order of
// the sums: tiled and clustered add a pixel's global lights before its cluster's list
// (render/culling/ClusterLists.h), each in the lights' order, where forward adds all in the
// lights' order (and both group them differently past a light batch). Two orders of n
// non-negative terms differ by at most 2 (n - 1) 2^-24 relative, within the tolerance up to
// 84 lights in range of a pixel; past that the bound is the statistics of the roundings: the
// cases with global lights differ by at most 3.5% of the tolerance (measured: bunny_teapot,
// spots_points_300, pbr_models and glass_transparency_two_batches, whose pixels have up to 351
// lights in range, 556 of its 9,000 global at 128x72).
//
// Compact layout (the default): the G-buffer rounds kd and ks to 8 bits, so the bound follows
// from the quantisation (docs/testing.md). Per channel, colour = ke + kd·D + ks·S with D, S ≥ 0
// the sums of everything a light or the ambient term multiplies kd and ks by. Rounding kd to
// 8 bits changes it by ≤ q = 0.5/255, so kd·D changes by ≤ q·D ≤ (q / kd)·colour; the same for
// ks. ke is stored as a half float (≤ 2^-10 relative, llvmpipe truncates). The octahedral normal
// (RG16, ≤ 5e-5 measured) moves N·L by as much and the specular lobe by up to √s·e^-½ times that
// (≈ 5 for s = 64): 3e-4 relative. The view depth is stored as its 32-bit float's bits, and
// forward and the deferred passes build the shaded point from that depth with one precise
// function (docs/lighting.md, "The shaded point"): the same point, bit for bit. (It was the
// interpolated position in forward, which an NVIDIA H100's sub-pixel snapping moved off the
// pixel's ray; where a light's cut-off sphere passed between the two points, 5 values of the
// default scene differed by a whole light's contribution at its cut, 3.7 times this bound.)
// The shininess code (16 bits) moves (N·H)^s by ≤ 3.1e-5 of ks·I. Every 8-bit and 16-bit
// code is made by GLSL's packUnorm functions, round(clamp(c, 0, 1) · (2^b − 1)) (GLSL 4.50
// §8.4): within half a step, unlike a fixed-function conversion to a unorm target, which may
// give either neighbour (GL 4.6 §2.3.5.2). So, with kd and ks of the pixel taken from the seed layout's --view
// diffuse/specular:
//   |Δ| ≤ |forward| · (q/kd + q/ks + 2^-10 + 3e-4) + 1e-5 · |forward| + 1e-6.
// Forward's image is the seed layout's to 1e-5 (the seed cases), so this also bounds the
// compact layout against the seed layout.
//
// Under the GPU driver profile (the image.gpu. tests, docs/testing.md) every technique,
// forward too, is compared with forward under the software profile, with the same tolerances:
// the two profiles differ in how the lights are read (bit for bit the same values) and in the
// specular powers, pow() against multiplications, whose difference is a few ulps of the
// specular term (tests/gl/SpecularPowerTest.cpp), within the 1e-5 relative. The third
// difference, 8x anisotropic filtering for `--anisotropy auto`, changes what the textures give
// by design (more texels averaged, far beyond any tolerance on the textured cases): the
// reference is rendered with the GPU's anisotropy, so that the comparison is of the code paths.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "TestSupport.h"
#include "render/Techniques.h"
#include "render/scene/TextureCache.h"
#include "render/techniques/Technique.h"
#include "tests/support/ImageComparison.h"

namespace manylights {
namespace {

using test::renderPfm;
using test::scratchDirectory;
using test::writeFile;

// Relative error the compact layout's 8-bit rounding of a material channel k can cause in
// everything k multiplies (see the top of this file); 0 for k = 0, which rounds exactly.
double eightBitRelativeError(double k)
{
    constexpr double kHalfStep = 0.5 / 255.0;
    return k > 0.0 ? kHalfStep / k : 0.0;
}

// `diffuse` and `specular` are the seed layout's --view diffuse and specular of the scene.
void expectWithinCompactTolerance(const Image& reference, const Image& candidate, const Image& diffuse,
                                  const Image& specular, const std::string& what)
{
    ASSERT_EQ(reference.rgb.size(), candidate.rgb.size());
    ASSERT_EQ(reference.rgb.size(), diffuse.rgb.size());
    ASSERT_EQ(reference.rgb.size(), specular.rgb.size());
    constexpr double kHalfFloatEmissive = 1.0 / 1024.0;
    constexpr double kNormalEncoding = 3e-4;
    EXPECT_TRUE(test::imagesNear(reference, candidate, [&](std::size_t i, double want) {
        const double relative = eightBitRelativeError(diffuse.rgb[i]) + eightBitRelativeError(specular.rgb[i]) +
                                kHalfFloatEmissive + kNormalEncoding + test::kAgreementTolerance.relative;
        return relative * std::abs(want) + test::kAgreementTolerance.absolute;
    })) << what;
}

struct AgreementCase {
    std::string name;
    std::string scene;  // path, or "" for the default scene
    std::vector<std::string> args;
    // With the compact G-buffer and its derived tolerance; otherwise the exact seed layout.
    bool compact = false;
    // Names the case in test listings instead of dumping its bytes.
    friend void PrintTo(const AgreementCase& c, std::ostream* os) { *os << c.name; }
};

class TechniqueAgreement : public ::testing::TestWithParam<AgreementCase> {};

TEST_P(TechniqueAgreement, EveryTechniqueMatchesForward)
{
    const AgreementCase& c = GetParam();
    const auto dir = scratchDirectory();
    std::vector<std::string> layoutArgs = c.args;
    layoutArgs.insert(layoutArgs.end(), {"--gbuffer", c.compact ? "compact" : "seed"});
    // Under the GPU profile, the reference is forward as a software rasteriser renders it.
    const bool otherProfile = !test::testDriverProfile().empty() && test::testDriverProfile() != "software";
    std::vector<std::string> args = layoutArgs;
    args.insert(args.end(), {"--technique", "forward"});
    if (otherProfile)
        args.insert(args.end(), {"--driver-profile", "software", "--anisotropy", std::to_string(kHardwareAnisotropy)});
    const Image reference = renderPfm(c.scene, dir / "reference.pfm", args);
    Image diffuse;
    Image specular;
    if (c.compact) {
        std::vector<std::string> viewArgs = c.args;
        viewArgs.insert(viewArgs.end(), {"--gbuffer", "seed", "--view", "diffuse"});
        diffuse = renderPfm(c.scene, dir / "diffuse.pfm", viewArgs);
        viewArgs.back() = "specular";
        specular = renderPfm(c.scene, dir / "specular.pfm", viewArgs);
    }
    for (const std::string& technique : techniqueNames()) {
        if (technique == "forward" && !otherProfile)
            continue;
        std::vector<std::string> techniqueArgs = layoutArgs;
        techniqueArgs.insert(techniqueArgs.end(), {"--technique", technique});
        const Image image = renderPfm(c.scene, dir / (technique + ".pfm"), techniqueArgs);
        if (c.compact)
            expectWithinCompactTolerance(reference, image, diffuse, specular, technique);
        else
            test::expectImagesNear(reference, image, test::kAgreementTolerance, technique);
    }
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, TechniqueAgreement,
    ::testing::Values(
        AgreementCase{"default_scene", "", {"--size", "320x180"}},
        AgreementCase{"default_scene_1024_lights", "", {"--size", "192x108", "--lights", "1024"}},
        // Mid-animation: lights, markers and objects moved, the dynamic surface of
        // revolution computed in the vertex shader at this time.
        AgreementCase{"default_scene_at_time_2_7", "", {"--size", "192x108", "--time", "2.7"}},
        AgreementCase{
            "spots_points_wide_cone_unbounded", test::kTestScenes + "spots_and_points.json", {"--size", "240x160"}},
        AgreementCase{"spots_points_300_set_lights",
                      test::kTestScenes + "spots_and_points.json",
                      {"--size", "160x120", "--lights", "300"}},
        // The camera cases of the light-volume techniques (tests/scenes/*.json say
        // how each is set up).
        AgreementCase{
            "camera_inside_point_light", test::kTestScenes + "camera_inside_point_light.json", {"--size", "160x120"}},
        AgreementCase{
            "camera_inside_spot_cone", test::kTestScenes + "camera_inside_spot_cone.json", {"--size", "160x120"}},
        AgreementCase{
            "light_cut_by_near_plane", test::kTestScenes + "light_cut_by_near_plane.json", {"--size", "160x120"}},
        AgreementCase{
            "light_beyond_far_plane", test::kTestScenes + "light_beyond_far_plane.json", {"--size", "160x120"}},
        AgreementCase{"spot_cutoff_120", test::kTestScenes + "spot_cutoff_120.json", {"--size", "160x120"}},
        AgreementCase{"unbounded_light", test::kTestScenes + "unbounded_light.json", {"--size", "160x120"}},
        AgreementCase{
            "small_lights_behind_walls", test::kTestScenes + "small_lights_behind_walls.json", {"--size", "160x90"}},
        // Surfaces drawn at exactly the same depths, lit in two light batches: the G-buffer
        // keeps the first drawn; forward's lighting draws after its depth pre-pass must too,
        // and shade it once per batch, not once per surface that ties.
        AgreementCase{"coplanar_surfaces", test::kTestScenes + "coplanar_surfaces.json", {"--size", "160x90"}},
        // Diffuse, specular and normal maps (issue 5): the G-buffer must carry the
        // textured, normal-mapped surface exactly as forward shades it.
        AgreementCase{
            "textured_normal_mapped", test::kTestScenes + "textured_normal_mapped.json", {"--size", "200x120"}},
        // The compact layout (the default) against forward within its derived bound.
        AgreementCase{"compact_default_scene", "", {"--size", "256x144"}, true},
        AgreementCase{
            "compact_spots_and_points", test::kTestScenes + "spots_and_points.json", {"--size", "160x120"}, true},
        AgreementCase{"compact_textured_normal_mapped",
                      test::kTestScenes + "textured_normal_mapped.json",
                      {"--size", "200x120"},
                      true},
        // Full-resolution OBJ models (69k and 6k triangles) under many small lights.
        AgreementCase{"bunny_teapot_models",
                      MANYLIGHTS_SOURCE_DIR "/scenes/bunny-teapot.json",
                      {"--size", "160x90", "--lights", "512"}},
        // Shadows (directional, spot maps, cube maps for points and wide spots)
        // and SSAO: every technique samples the same maps at the same positions.
        AgreementCase{"shadows_and_ssao",
                      test::kTestScenes + "shadows_and_ssao.json",
                      {"--size", "160x120", "--shadow-lights", "24"}},
        // Every light shadowed from the shadow-page pool (issue 47): the marking pass is the
        // same whatever the technique, so every technique reads the same pages with the same
        // lookup at the same shaded point. The default scene's 256 lights, and the courtyard
        // at 4,096 (its walls and pillars casting into most lights' faces).
        AgreementCase{"default_scene_all_shadowed", "", {"--size", "160x90", "--shadow-lights", "all"}},
        AgreementCase{"courtyard_4096_lights_all_shadowed",
                      MANYLIGHTS_SOURCE_DIR "/bench/courtyard.json",
                      {"--size", "128x72", "--lights", "4096", "--shadow-lights", "all"}},
        // Transparent panes and drops (the transparency pass, issue 16): over the
        // grid of the transparent objects' depths, against forward's every light;
        // past one light batch, the grid rebuilt per layer and batch.
        AgreementCase{"glass_transparency", MANYLIGHTS_SOURCE_DIR "/scenes/glass.json", {"--size", "320x180"}},
        // Both reflection models in one scene (issue 31): Blinn-Phong and metallic-roughness
        // surfaces side by side under every kind of light (a transparent metallic-roughness
        // ball in the transparency pass), and the textured glTF bottle of
        // scenes/pbr-models.json (base colour, occlusion-roughness-metallic, normal and
        // emissive maps) under its coloured lights.
        AgreementCase{"mixed_models", test::kTestScenes + "mixed_models.json", {"--size", "200x120"}},
        AgreementCase{"pbr_models_scene",
                      MANYLIGHTS_SOURCE_DIR "/scenes/pbr-models.json",
                      {"--size", "160x120", "--lights", "96"}},
        AgreementCase{"glass_transparency_two_batches",
                      MANYLIGHTS_SOURCE_DIR "/scenes/glass.json",
                      {"--size", "128x72", "--lights", "9000"}}),
    [](const ::testing::TestParamInfo<AgreementCase>& param) { return param.param.name; });

// The sizes people render at. A light whose sphere covers much of the view reaches tens of
// thousands of clusters there, and clustered once dropped such lights from 640x480 up while
// matching forward at every thumbnail size above (issue 11): the camera cases and a big
// light again, at 1280x720 and 800x600.
AgreementCase atSize(const std::string& scene, const std::string& size)
{
    std::string sizeName = size;
    std::replace(sizeName.begin(), sizeName.end(), 'x', '_');
    return AgreementCase{
        std::filesystem::path(scene).stem().string() + "_" + sizeName, test::kTestScenes + scene, {"--size", size}};
}

INSTANTIATE_TEST_SUITE_P(
    UserSizes, TechniqueAgreement,
    ::testing::Values(
        atSize("big_light.json", "1280x720"), atSize("big_light.json", "800x600"),
        atSize("camera_inside_point_light.json", "1280x720"), atSize("camera_inside_point_light.json", "800x600"),
        atSize("camera_inside_spot_cone.json", "1280x720"), atSize("camera_inside_spot_cone.json", "800x600"),
        atSize("light_cut_by_near_plane.json", "1280x720"), atSize("light_cut_by_near_plane.json", "800x600"),
        atSize("light_beyond_far_plane.json", "1280x720"), atSize("light_beyond_far_plane.json", "800x600"),
        atSize("spot_cutoff_120.json", "1280x720"), atSize("spot_cutoff_120.json", "800x600"),
        atSize("unbounded_light.json", "1280x720"), atSize("unbounded_light.json", "800x600"),
        atSize("spots_and_points.json", "1280x720"), atSize("mixed_models.json", "800x600"),
        // Tied surfaces under forward's depth pre-pass, over most of the screen.
        atSize("coplanar_surfaces.json", "1280x720")),
    [](const ::testing::TestParamInfo<AgreementCase>& param) { return param.param.name; });

}  // namespace
}  // namespace manylights
