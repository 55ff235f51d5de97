// The renderer's wait hook (RendererDesc::waitHook, PassProfiler::setWaitHook; issue 48): the
// viewer reads its input there, so that a key's press and release are timed within a pass, not
// a frame. It runs after every pass under every timing, and changes nothing in the image. How
// often it runs while a wait lasts depends on how long the GPU takes, so no test counts that.
#include <gtest/gtest.h>

#include <vector>

#include "GlContextTest.h"
#include "render/Renderer.h"
#include "scene/DefaultScene.h"
#include "scene/LightSets.h"

namespace manylights {
namespace {

class WaitHookTest : public GlContextTest {};

TEST_F(WaitHookTest, RunsAfterEveryPassAndLeavesTheImageAlone)
{
    const Scene scene = makeDefaultScene();
    const std::vector<Light> lights = expandLights(scene);
    for (PassTiming timing : {PassTiming::Wall, PassTiming::Gpu, PassTiming::Frame}) {
        int calls = 0;
        Renderer hooked(
            scene, lights,
            {.width = 96, .height = 54, .driver = {.passTiming = timing}, .waitHook = [&calls] { ++calls; }});
        Renderer plain(scene, lights, {.width = 96, .height = 54, .driver = {.passTiming = timing}});
        for (Renderer* renderer : {&hooked, &plain})
            renderer->setTime(0.7);
        const FrameSample sample = hooked.renderFrame("clustered", ViewMode::Final);
        plain.renderFrame("clustered", ViewMode::Final);
        // The sample sums a pass run per light batch into one entry: at least one call each.
        ASSERT_FALSE(sample.passes.empty());
        EXPECT_GE(calls, static_cast<int>(sample.passes.size())) << passTimingName(timing);
        EXPECT_EQ(hooked.readColour().rgb, plain.readColour().rgb) << passTimingName(timing);

        // Taken away by apply, the hook is not called again.
        RendererDesc withoutHook = hooked.desc();
        withoutHook.waitHook = {};
        hooked.apply(withoutHook);
        const int before = calls;
        hooked.renderFrame("clustered", ViewMode::Final);
        EXPECT_EQ(calls, before) << passTimingName(timing);
    }
}

}  // namespace
}  // namespace manylights
