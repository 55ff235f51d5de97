// Frames issued back to back (Renderer::queueFrame under PassTiming::Gpu), as a GPU's frames
// are timed (docs/performance.md, "Timing on a GPU"): nothing in a frame waits for the GPU,
// the light lists' status is read a frame or two late, and the images are those of frames
// rendered one at a time.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "GlContextTest.h"
#include "gl/Buffer.h"
#include "render/Renderer.h"
#include "scene/LightSets.h"
#include "scene/SceneLoader.h"

namespace manylights {
namespace {

class QueuedFramesTest : public GlContextTest {};

// A floor of 24 m under `count` point lights of 1 to 3 m range, drifting, within 6 m of its
// centre: many lights to a cluster, so that the first frame's planned storage cannot hold its
// pairs (ClusterLists::plan).
Scene floorScene(int count)
{
    nlohmann::json scene = {
        {"camera", {{"eye", {0, 12, 12}}, {"look_at", {0, 0, 0}}, {"fov_y", 50}, {"near", 0.5}, {"far", 60}}},
        {"ambient", {0.02, 0.02, 0.02}},
        {"light_sets",
         {{{"count", count},
           {"seed", 3},
           {"type", "point"},
           {"min", {-6, 0.1, -6}},
           {"max", {6, 1.5, 6}},
           {"range", {1, 3}},
           {"intensity", {0.05, 0.2}},
           {"animation", {{"drift", {{"amplitude", {1.5, 0.2, 1.5}}}}}}}}},
        {"materials", {{"m", {{"diffuse", {0.7, 0.7, 0.7}}, {"specular", {0.3, 0.3, 0.3}}, {"shininess", 16}}}}},
        {"objects", {{{"mesh", {{"primitive", "plane"}, {"size", {24, 24}}}}, {"material", "m"}}}}};
    return parseScene(scene.dump(), "<queued frames>", ".");
}

double counter(Technique& technique, const std::string& name)
{
    for (const TechniqueCounter& c : technique.counters())
        if (c.name == name)
            return c.value;
    ADD_FAILURE() << "no counter " << name;
    return 0.0;
}

TEST_F(QueuedFramesTest, BackToBackFramesReadNothingBackAndGiveTheImagesOfFramesWaitedFor)
{
    const Scene scene = floorScene(3000);
    const std::vector<Light> lights = expandLights(scene);
    for (const std::string technique : {"clustered", "tiled"}) {
        Renderer queued(scene, lights, {.width = 320, .height = 180, .driver = {.passTiming = PassTiming::Gpu}});
        Renderer waited(scene, lights, {.width = 320, .height = 180, .driver = {.passTiming = PassTiming::Wall}});
        Technique& queuedTechnique = queued.technique(technique);
        ASSERT_EQ(queued.passTiming(), PassTiming::Gpu);

        // Eight frames of the drifting lights issued back to back: none reads anything back
        // synchronously (the lists' status arrives through a mapped copy behind a fence), and
        // no more than kFramesInFlight are ever unfinished.
        std::vector<Renderer::FinishedFrame> finished;
        const std::uint64_t readsBefore = gl::Buffer::synchronousReads();
        constexpr int kFrames = 8;
        for (int frame = 0; frame < kFrames; ++frame) {
            queued.setTime(0.1 * frame);
            queued.queueFrame(queuedTechnique, ViewMode::Final);
            EXPECT_LE(queued.framesInFlight(), Renderer::kFramesInFlight);
            for (Renderer::FinishedFrame& done : queued.finishedFrames(false))
                finished.push_back(std::move(done));
        }
        for (Renderer::FinishedFrame& done : queued.finishedFrames(true))
            finished.push_back(std::move(done));
        EXPECT_EQ(gl::Buffer::synchronousReads(), readsBefore) << technique;
        ASSERT_EQ(finished.size(), static_cast<std::size_t>(kFrames)) << technique;
        EXPECT_EQ(queued.framesInFlight(), 0u);

        // The first frame's storage, planned before any frame said what it needs, is too small
        // (the frames issued before its status was read were built with it too): reported, and
        // counted as rebuilds; the frames built after it fit.
        EXPECT_FALSE(finished.front().fitted) << technique;
        int unfitted = 0;
        for (const Renderer::FinishedFrame& done : finished)
            unfitted += done.fitted ? 0 : 1;
        EXPECT_LE(unfitted, static_cast<int>(Renderer::kFramesInFlight)) << technique;
        EXPECT_TRUE(finished.back().fitted) << technique;
        EXPECT_EQ(counter(queuedTechnique, "cluster_rebuilds"), unfitted) << technique;

        // Each sample has the passes' GPU times and no wall times (no pass was waited for).
        for (const Renderer::FinishedFrame& done : finished) {
            EXPECT_EQ(done.sample.timing, PassTiming::Gpu);
            ASSERT_FALSE(done.sample.passes.empty());
            for (const PassSample& pass : done.sample.passes) {
                EXPECT_TRUE(pass.gpuMs) << pass.name;
                EXPECT_FALSE(pass.wallMs) << pass.name;
            }
        }

        // The last frame's image is the one a renderer that waits for each frame makes at that
        // time, to the byte: the same lists in the same order.
        waited.setTime(0.1 * (kFrames - 1));
        waited.renderFrame(technique, ViewMode::Final);
        EXPECT_EQ(queued.readColour().rgb, waited.readColour().rgb) << technique;
    }
}

TEST_F(QueuedFramesTest, RenderFrameWaitsForItsFrameUnderEveryTiming)
{
    // renderFrame under the GPU's timing issues the frame like any other and waits for it:
    // the image of PassTiming::Wall, and the same storage check (a first frame that overflows
    // its lists is rendered again).
    const Scene scene = floorScene(3000);
    const std::vector<Light> lights = expandLights(scene);
    std::map<PassTiming, std::vector<float>> images;
    for (PassTiming timing : {PassTiming::Wall, PassTiming::Gpu, PassTiming::Frame}) {
        Renderer renderer(scene, lights, {.width = 320, .height = 180, .driver = {.passTiming = timing}});
        const FrameSample sample = renderer.renderFrame("clustered", ViewMode::Final);
        EXPECT_EQ(sample.timing, timing);
        EXPECT_GT(sample.wallMs, 0.0);
        EXPECT_GE(counter(renderer.technique("clustered"), "cluster_rebuilds"), 1.0);
        for (const PassSample& pass : sample.passes) {
            EXPECT_EQ(pass.wallMs.has_value(), timing == PassTiming::Wall) << pass.name;
            EXPECT_EQ(pass.gpuMs.has_value(), timing != PassTiming::Frame) << pass.name;
        }
        images[timing] = renderer.readColour().rgb;
    }
    EXPECT_EQ(images[PassTiming::Gpu], images[PassTiming::Wall]);
    EXPECT_EQ(images[PassTiming::Frame], images[PassTiming::Wall]);
}

}  // namespace
}  // namespace manylights
