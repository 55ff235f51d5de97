// The renderer's one route for settings (RendererDesc, Renderer::apply), the technique
// variants it makes and keeps, and its camera.
#include <gtest/gtest.h>

#include <optional>

#include "GlContextTest.h"
#include "core/Error.h"
#include "render/Renderer.h"
#include "render/Techniques.h"
#include "scene/LightSets.h"
#include "scene/SceneLoader.h"
#include "scene/ShadowSelection.h"
#include "tests/support/ImageComparison.h"

namespace manylights {
namespace {

class RendererTest : public GlContextTest {};

const char* kScene = R"({
    "camera": {"eye": [0, 4, 6], "look_at": [0, 0, 0], "fov_y": 50},
    "ambient": [0.05, 0.05, 0.05],
    "lights": [{"type": "point", "pos": [1, 2, 1], "intensity": [3, 2, 1], "range": 8}],
    "objects": [
        {"mesh": {"primitive": "plane", "size": [10, 10]}},
        {"mesh": {"primitive": "box", "size": [1, 1, 1]}, "transform": {"translate": [1, 0.5, 0]}}]})";

TEST_F(RendererTest, ZerosInTheDescStandForTheDefaults)
{
    const Scene scene = parseScene(kScene, "<renderer test>", ".");
    const Renderer renderer(scene, expandLights(scene));
    EXPECT_EQ(renderer.width(), kDefaultImageWidth);
    EXPECT_EQ(renderer.height(), kDefaultImageHeight);
    EXPECT_EQ(renderer.desc().supersample, 1);
    EXPECT_FALSE(renderer.desc().countWork);
    EXPECT_EQ(renderer.desc().shadowLights, 0);
    EXPECT_EQ(renderer.shadowPool().poolMiB(), kDefaultShadowPoolMiB);
}

TEST_F(RendererTest, TechniqueVariantsFollowTheSettingsAndAreMadeOnce)
{
    const Scene scene = parseScene(kScene, "<renderer test>", ".");
    RendererDesc desc{.width = 64, .height = 48};
    Renderer renderer(scene, expandLights(scene), desc);
    Technique& plain = renderer.technique("deferred");
    EXPECT_EQ(plain.name(), "deferred");
    EXPECT_FALSE(plain.options().shaders.countWork);
    EXPECT_FALSE(plain.options().shaders.localShadows);
    EXPECT_EQ(&renderer.technique("deferred"), &plain);

    desc.countWork = true;
    renderer.apply(desc);
    Technique& counting = renderer.technique("deferred");
    EXPECT_NE(&counting, &plain);
    EXPECT_TRUE(counting.options().shaders.countWork);

    desc.countWork = false;
    desc.shadowLights = 2;
    renderer.apply(desc);
    Technique& shadowed = renderer.technique("deferred");
    EXPECT_TRUE(shadowed.options().shaders.localShadows);
    EXPECT_EQ(renderer.desc().shadowLights, 2);

    // Back to the first settings: the first variant again, not a new one.
    desc.shadowLights = 0;
    renderer.apply(desc);
    EXPECT_EQ(&renderer.technique("deferred"), &plain);
}

TEST_F(RendererTest, UnknownTechniqueAndImpossibleSizeAreErrorsThatChangeNothing)
{
    const Scene scene = parseScene(kScene, "<renderer test>", ".");
    Renderer renderer(scene, expandLights(scene), {.width = 64, .height = 48});
    EXPECT_THROW(renderer.technique("raytraced"), Error);
    EXPECT_THROW(renderer.apply({.width = 1 << 20, .height = 48}), Error);
    EXPECT_EQ(renderer.desc().width, 64);
    EXPECT_EQ(renderer.width(), 64);
    renderer.renderFrame("deferred", ViewMode::Final);
}

TEST_F(RendererTest, SetCameraMovesTheViewAndTheScenesCameraRestoresIt)
{
    const Scene scene = parseScene(kScene, "<renderer test>", ".");
    Renderer renderer(scene, expandLights(scene), {.width = 64, .height = 48});
    renderer.renderFrame("deferred", ViewMode::Final);
    const Image first = renderer.readColour();

    Camera moved = scene.camera;
    moved.eye = {4.0f, 3.0f, 2.0f};
    renderer.setCamera(moved);
    renderer.renderFrame("deferred", ViewMode::Final);
    const Image elsewhere = renderer.readColour();
    int differing = 0;
    for (std::size_t i = 0; i < first.rgb.size(); ++i)
        differing += first.rgb[i] != elsewhere.rgb[i];
    EXPECT_GT(differing, static_cast<int>(first.rgb.size() / 4)) << "the moved camera should see another image";

    // The same frame as the first: exactly the same pixels.
    renderer.setCamera(scene.camera);
    renderer.renderFrame("deferred", ViewMode::Final);
    test::expectImagesNear(renderer.readColour(), first, test::Tolerance{});
}

// The viewer's switches of the ambient, diffuse and specular terms (RendererDesc::lightingTerms),
// which the techniques' shaders read in different ways: the light volumes as flat varyings from
// their vertex shader, the others from the frame's uniform block (lib/frame.glsl). With the
// terms switched on one at a time, every technique gives deferred's image within the agreement
// tolerance (the same G-buffer, the same lighting function), and in every technique, forward
// included, the three images add up to the image with all three on: the emissive term, which no
// switch turns off, is in each of them, so the image with all three off is taken away twice.
TEST_F(RendererTest, TermSwitchesAgreeInEveryTechniqueAndAddUp)
{
    const Scene scene = parseScene(R"({
        "camera": {"eye": [0, 4, 6], "look_at": [0, 0, 0], "fov_y": 50},
        "ambient": [0.1, 0.1, 0.1],
        "directional": {"direction": [-1, -2, -1], "intensity": [0.3, 0.3, 0.3]},
        "materials": {"shiny": {"diffuse": [0.6, 0.4, 0.3], "specular": [0.5, 0.5, 0.5], "shininess": 24,
                                "emissive": [0.02, 0.01, 0.0]}},
        "lights": [{"type": "point", "pos": [1, 2, 1], "intensity": [3, 2, 1], "range": 8},
                   {"type": "point", "pos": [-2, 1, 0], "intensity": [1, 2, 3], "range": 6},
                   {"type": "spot", "pos": [0, 3, 2], "direction": [0, -1, -0.5], "cutoff": 35,
                    "intensity": [2, 2, 2], "range": 9}],
        "objects": [
            {"mesh": {"primitive": "plane", "size": [10, 10]}, "material": "shiny"},
            {"mesh": {"primitive": "sphere", "radius": 1}, "material": "shiny",
             "transform": {"translate": [0.5, 1, 0]}}]})",
                                   "<renderer test>", ".");
    RendererDesc desc{.width = 96, .height = 64};
    Renderer renderer(scene, expandLights(scene), desc);
    const auto render = [&](const std::string& technique, glm::vec3 terms) {
        desc.lightingTerms = terms;
        renderer.apply(desc);
        renderer.renderFrame(technique, ViewMode::Final);
        return renderer.readColour();
    };
    const glm::vec3 ambientOnly{1, 0, 0}, diffuseOnly{0, 1, 0}, specularOnly{0, 0, 1};
    const Image deferredDiffuse = render("deferred", diffuseOnly);
    const Image deferredSpecular = render("deferred", specularOnly);
    for (const std::string& technique : techniqueNames()) {
        const Image all = render(technique, {1, 1, 1});
        const Image none = render(technique, {0, 0, 0});
        const Image ambient = render(technique, ambientOnly);
        const Image diffuse = render(technique, diffuseOnly);
        const Image specular = render(technique, specularOnly);
        Image sum = all;
        for (std::size_t i = 0; i < sum.rgb.size(); ++i)
            sum.rgb[i] = ambient.rgb[i] + diffuse.rgb[i] + specular.rgb[i] - 2.0f * none.rgb[i];
        test::expectImagesNear(all, sum, test::kAgreementTolerance, technique + ": the terms add up");
        if (technique != "forward") {
            test::expectImagesNear(deferredDiffuse, diffuse, test::kAgreementTolerance, technique + ": diffuse only");
            test::expectImagesNear(deferredSpecular, specular, test::kAgreementTolerance,
                                   technique + ": specular only");
        }
    }
    // The switches do something: each term alone is a different image.
    EXPECT_FALSE(test::imagesNear(deferredDiffuse, deferredSpecular, test::kAgreementTolerance));
}

// The light texels hold the light buffer's bytes: a light read through them, through the
// storage buffer or through a uniform window is the same floats, so the image is the same bit
// for bit (Tolerance{} is zero) where the batches are the same, in every technique that reads lights in the fragment or
// compute shader. Without texels a software rasteriser reads windows where the scene fits one
// (500 lights) and the storage buffer beyond (2,000), so each path is compared with the
// texels. The transparency pass is covered by glass.json in TechniqueAgreementTest. Five of
// the lights reach the whole view, and at this size many of the others cover half of it: tiled
// and clustered read those from their global lists (render/culling/ClusterLists.h), through
// texels or storage buffers too.
TEST_F(RendererTest, LightTexelsWindowsAndTheStorageBufferGiveTheSameImage)
{
    for (const int lightCount : {500, 2000}) {
        const Scene scene = parseScene(R"({
            "camera": {"eye": [0, 6, 9], "look_at": [0, 0, 0], "fov_y": 50},
            "light_sets": [{"count": )" + std::to_string(lightCount) +
                                           R"(, "seed": 7, "type": "point", "min": [-5, 0.2, -5],
                            "max": [5, 1, 5], "range": [1, 2.5], "intensity": [0.1, 0.4]},
                           {"count": 5, "seed": 8, "type": "point", "min": [-5, 0.2, -5],
                            "max": [5, 1, 5], "range": [30, 40], "intensity": [0.01, 0.04]}],
            "objects": [
                {"mesh": {"primitive": "plane", "size": [12, 12]}},
                {"mesh": {"primitive": "sphere", "radius": 1}, "transform": {"translate": [1, 1, 0]}}]})",
                                       "<renderer test>", ".");
        RendererDesc desc{.width = 96, .height = 64};
        Renderer renderer(scene, expandLights(scene), desc);
        if (renderer.gpuScene().indexedLightSource() != LightSource::TexelBuffer)
            GTEST_SKIP() << "the driver has no light texels (render/programs/LightBatches.h)";
        for (const char* technique : {"forward", "deferred", "tiled-quads", "tiled", "clustered"}) {
            const std::string what = std::string(technique) + ", " + std::to_string(lightCount) + " lights";
            desc.lightTexels = true;
            renderer.apply(desc);
            if (renderer.driverChoices().lightTexelsBeforeWindows) {
                EXPECT_EQ(renderer.gpuScene().walkedLightSource(), LightSource::TexelBuffer) << what;
            }
            renderer.renderFrame(technique, ViewMode::Final);
            const Image texels = renderer.readColour();
            for (const TechniqueCounter& counter : renderer.technique(technique).counters()) {
                if (counter.name == "global_lights") {
                    EXPECT_GE(counter.value, 5.0) << what;
                }
            }
            desc.lightTexels = false;
            renderer.apply(desc);
            EXPECT_EQ(renderer.gpuScene().indexedLightSource(), LightSource::StorageBuffer);
            // So that the windows are what the texels are compared with, where a batch fits one.
            EXPECT_EQ(renderer.gpuScene().walkedLightSource(), LightSource::UniformWindow);
            renderer.renderFrame(technique, ViewMode::Final);
            // Windows hold 1,024 lights: forward and deferred then add 2,000 lights in two
            // batches, a different grouping of the same sum (agreement tolerance).
            const bool sameBatches = lightCount <= static_cast<int>(kLightsPerWindow) ||
                                     (std::string(technique) != "forward" && std::string(technique) != "deferred");
            test::expectImagesNear(renderer.readColour(), texels,
                                   sameBatches ? test::Tolerance{} : test::kAgreementTolerance, what);
        }
    }
}

// The same at the size users render and past 65,536 lights: 70,000 small lights over a wide
// floor at 1280x720, nine light batches of the culling techniques, whose light indices run
// past 16 bits (the coarse tiles of tiled, the cluster masks, tiled-quads' tile points). The
// texels and the storage buffer give the same image bit for bit, and the three culling
// techniques give the same image as one another within the agreement tolerance (each keeps
// the lights of a pixel in its own batches and tile runs, so the sums are grouped
// differently). Forward, the reference, is out of reach at this size: 70,000 lights for
// every fragment (TechniqueAgreementTest compares each of them with it on smaller scenes).
TEST_F(RendererTest, LightSourcesAndCullingTechniquesAgreePastSixtyFiveThousandLights)
{
    const Scene scene = parseScene(R"({
        "camera": {"eye": [0, 70, 55], "look_at": [0, 0, 0], "fov_y": 60, "far": 400},
        "light_sets": [{"count": 70000, "seed": 11, "type": "point", "min": [-50, 0.2, -50],
                        "max": [50, 1.5, 50], "range": [0.5, 1.5], "intensity": [0.05, 0.2]}],
        "objects": [
            {"mesh": {"primitive": "plane", "size": [100, 100]}},
            {"mesh": {"primitive": "sphere", "radius": 6}, "transform": {"translate": [5, 6, 0]}}]})",
                                   "<renderer test>", ".");
    RendererDesc desc{.width = 1280, .height = 720};
    Renderer renderer(scene, expandLights(scene), desc);
    if (renderer.gpuScene().indexedLightSource() != LightSource::TexelBuffer)
        GTEST_SKIP() << "the driver has no light texels (render/programs/LightBatches.h)";
    std::optional<Image> clustered;
    for (const char* technique : {"clustered", "tiled", "tiled-quads"}) {
        desc.lightTexels = true;
        renderer.apply(desc);
        renderer.renderFrame(technique, ViewMode::Final);
        const Image texels = renderer.readColour();
        desc.lightTexels = false;
        renderer.apply(desc);
        renderer.renderFrame(technique, ViewMode::Final);
        test::expectImagesNear(renderer.readColour(), texels, test::Tolerance{}, technique);
        if (!clustered)
            clustered = texels;
        else
            test::expectImagesNear(*clustered, texels, test::kAgreementTolerance, technique);
    }
}

// forward's lighting draws let one fragment per pixel through per light batch with the
// stencil, testing it against the batch's number (Stencil::OncePerPixel): past 256 batches the
// stencil must wrap as the 8-bit reference does (GL_INCR_WRAP). Without light texels llvmpipe
// reads windows of 1,024 lights, as a GPU does, so 307,200 lights on one spot are 300 batches.
// The image must be the one-light image times the lights' summed intensity: a stencil that
// saturated at 255 would drop the last 44 batches (14% of the light), while float rounding of
// 307,200 terms stays under 307,200 · 2^-24 = 1.8% (tests/image/ManyLightsTest.cpp says why).
TEST_F(RendererTest, ForwardAddsEveryLightPastTwoHundredFiftySixBatches)
{
    constexpr int kLights = 307200;
    constexpr double kTolerance = 0.02;
    static_assert(kLights * 0x1p-24 < kTolerance);
    const std::string scenes = MANYLIGHTS_SOURCE_DIR "/tests/scenes/";
    const Scene one = loadSceneFile(scenes + "one_light_on_one_spot.json");
    Scene many = loadSceneFile(scenes + "lights_on_one_spot.json");
    ASSERT_EQ(many.lightSets.size(), 1u);
    many.lightSets[0].count = kLights;
    const std::vector<Light> lights = expandLights(many);
    double total[3] = {0.0, 0.0, 0.0};
    for (const Light& light : lights)
        for (int c = 0; c < 3; ++c)
            total[c] += light.intensity[c];

    const RendererDesc desc{.width = 1280, .height = 720, .lightTexels = false};
    Renderer oneRenderer(one, expandLights(one), desc);
    oneRenderer.renderFrame("forward", ViewMode::Final);
    const Image oneImage = oneRenderer.readColour();
    Renderer renderer(many, lights, desc);
    if (!renderer.gpuScene().readsLightWindows())
        GTEST_SKIP() << "the driver has no light windows (render/programs/LightBatches.h)";
    renderer.renderFrame("forward", ViewMode::Final);
    Image expected = oneImage;
    int lit = 0;
    for (std::size_t i = 0; i < expected.rgb.size(); ++i) {
        expected.rgb[i] = static_cast<float>(static_cast<double>(oneImage.rgb[i]) * total[i % 3]);
        lit += expected.rgb[i] > 0.0f;
    }
    EXPECT_GE(lit, 3) << "the square should cover a pixel";
    test::expectImagesNear(expected, renderer.readColour(), {.relative = kTolerance});
}

}  // namespace
}  // namespace manylights
