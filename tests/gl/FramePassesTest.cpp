// Passes as records (render/FramePasses.h): the barriers, the pipeline state and the timed
// scopes that FramePasses derives from them.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "OnePlaneFrameTest.h"

namespace manylights {
namespace {

class FramePassesTest : public OnePlaneFrameTest {};

constexpr Pass kComputeStoresLit{.name = "store", .images = Resource::LitImage, .writes = Resource::LitImage};
constexpr Pass kSamplesLit{.name = "sample", .target = Resource::GBuffer, .sampled = Resource::LitImage};
constexpr Pass kDrawsIntoLit{.name = "draw", .target = Resource::LitImage};
constexpr Pass kComputeWritesGrid{.name = "grid", .storage = Resource::LightGrid, .writes = Resource::LightGrid};
constexpr Pass kDrawReadsGrid{.name = "shade", .target = Resource::LitImage, .storage = Resource::LightGrid};

TEST_F(FramePassesTest, BarriersFollowIncoherentWritesAndQueuedDraws)
{
    profiler_.beginFrame();
    FramePasses passes(gpuScene_, targets_, profiler_);
    // The lit image was cleared (a draw command): a compute pass storing to it waits for that.
    EXPECT_EQ(passes.barrierFor(kComputeStoresLit), GLbitfield{GL_SHADER_IMAGE_ACCESS_BARRIER_BIT});
    passes.run(kComputeStoresLit, [] {});
    // The stores: each later kind of access waits on its own bit, once.
    EXPECT_EQ(passes.barrierFor(kDrawsIntoLit), GLbitfield{GL_FRAMEBUFFER_BARRIER_BIT});
    EXPECT_EQ(passes.barrierFor(kSamplesLit), GLbitfield{GL_TEXTURE_FETCH_BARRIER_BIT});
    EXPECT_EQ(passes.barrierFor(kComputeStoresLit), GLbitfield{GL_SHADER_IMAGE_ACCESS_BARRIER_BIT});
    passes.run(kSamplesLit, [] {});
    EXPECT_EQ(passes.barrierFor(kSamplesLit), GLbitfield{0});
    passes.run(kDrawsIntoLit, [] {});
    EXPECT_EQ(passes.barrierFor(kDrawsIntoLit), GLbitfield{0}) << "draws after draws are ordered";

    // A grid rebuilt by compute after draws that read it waits for those draws (llvmpipe runs
    // compute work at once but queues draws); the draws after it wait for its writes.
    passes.run(kComputeWritesGrid, [] {});
    EXPECT_EQ(passes.barrierFor(kDrawReadsGrid), GLbitfield{GL_SHADER_STORAGE_BARRIER_BIT});
    passes.run(kDrawReadsGrid, [] {});
    EXPECT_EQ(passes.barrierFor(kDrawReadsGrid), GLbitfield{0});
    EXPECT_EQ(passes.barrierFor(kComputeWritesGrid),
              GLbitfield{GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT});

    // An indirect dispatch whose parameters compute wrote waits on the command bit; a copy of a
    // buffer that compute wrote on the buffer-update bit.
    constexpr Pass kIndirect{.name = "indirect", .storage = Resource::LightGrid, .indirect = Resource::LightGrid};
    constexpr Pass kCopy{.name = "copy", .transfers = Resource::LightGrid};
    passes.run(kComputeWritesGrid, [] {});
    EXPECT_EQ(passes.barrierFor(kIndirect), GLbitfield{GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT});
    EXPECT_EQ(passes.barrierFor(kCopy), GLbitfield{GL_BUFFER_UPDATE_BARRIER_BIT});
    passes.run(kIndirect, [] {});
    EXPECT_EQ(passes.barrierFor(kCopy), GLbitfield{GL_BUFFER_UPDATE_BARRIER_BIT});
    passes.finish();
    profiler_.endFrame();
}

TEST_F(FramePassesTest, APassDrawsWithItsStateAndLeavesGlsDefaults)
{
    profiler_.beginFrame();
    FramePasses passes(gpuScene_, targets_, profiler_);
    GLint depthFunction = 0;
    GLboolean depthWrites = GL_TRUE;
    GLboolean blending = GL_FALSE;
    GLint boundFramebuffer = 0;
    passes.run({.name = "add", .target = Resource::LitImage, .state = kAddToCoveredPixels}, [&] {
        glGetIntegerv(GL_DEPTH_FUNC, &depthFunction);
        glGetBooleanv(GL_DEPTH_WRITEMASK, &depthWrites);
        blending = glIsEnabled(GL_BLEND);
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &boundFramebuffer);
    });
    EXPECT_EQ(depthFunction, GL_GREATER);
    EXPECT_EQ(depthWrites, GL_FALSE);
    EXPECT_EQ(blending, GL_TRUE);
    EXPECT_EQ(static_cast<GLuint>(boundFramebuffer), targets_.litFramebuffer.id());

    glGetIntegerv(GL_DEPTH_FUNC, &depthFunction);
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depthWrites);
    EXPECT_EQ(depthFunction, GL_LESS);
    EXPECT_EQ(depthWrites, GL_TRUE);
    EXPECT_EQ(glIsEnabled(GL_BLEND), GL_FALSE);
    EXPECT_EQ(glIsEnabled(GL_STENCIL_TEST), GL_FALSE);
    passes.finish();
    profiler_.endFrame();
}

TEST_F(FramePassesTest, PassesOfOneNameAreOneTimedPass)
{
    profiler_.beginFrame();
    {
        FramePasses passes(gpuScene_, targets_, profiler_);
        for (const char* name : {"geometry", "lighting", "lighting", "lighting", "clusters", "lighting"})
            passes.run({.name = name}, [] {});
    }
    // Consecutive passes of one name (a pass per light batch) share one scope: one pair of
    // glFinish calls, not one per batch.
    EXPECT_EQ(profiler_.scopesThisFrame(), 4u);
    const FrameSample frame = profiler_.endFrame();
    std::vector<std::string> names;
    for (const PassSample& pass : frame.passes)
        names.push_back(pass.name);
    // The profiler sums the scopes of one name into one entry.
    EXPECT_EQ(names, (std::vector<std::string>{"geometry", "lighting", "clusters"}));
}

}  // namespace
}  // namespace manylights
