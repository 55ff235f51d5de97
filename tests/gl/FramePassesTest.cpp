// Passes as records (render/frame/FramePasses.h): the barriers, the pipeline state and the timed
// scopes that FramePasses derives from them.
#include <gtest/gtest.h>

#include <array>
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

// The faces, depth bias, viewport, scissor, point size and polygon mode of a record, read back
// inside its pass and after it.
struct FaceAndRasterState {
    GLboolean culling = GL_FALSE;
    GLint culledFace = 0;
    GLint frontFace = 0;
    GLboolean depthBias = GL_FALSE;
    GLfloat slopeScaledBias = 0.0f;
    GLfloat constantBias = 0.0f;
    std::array<GLint, 4> viewport{};
    GLboolean scissorTest = GL_FALSE;
    std::array<GLint, 4> scissor{};
    GLboolean pointSizeFromShader = GL_FALSE;
    GLfloat pointSize = 0.0f;
    std::array<GLint, 2> polygonMode{};

    static FaceAndRasterState read()
    {
        FaceAndRasterState state;
        state.culling = glIsEnabled(GL_CULL_FACE);
        glGetIntegerv(GL_CULL_FACE_MODE, &state.culledFace);
        glGetIntegerv(GL_FRONT_FACE, &state.frontFace);
        state.depthBias = glIsEnabled(GL_POLYGON_OFFSET_FILL);
        glGetFloatv(GL_POLYGON_OFFSET_FACTOR, &state.slopeScaledBias);
        glGetFloatv(GL_POLYGON_OFFSET_UNITS, &state.constantBias);
        glGetIntegerv(GL_VIEWPORT, state.viewport.data());
        state.scissorTest = glIsEnabled(GL_SCISSOR_TEST);
        glGetIntegerv(GL_SCISSOR_BOX, state.scissor.data());
        state.pointSizeFromShader = glIsEnabled(GL_PROGRAM_POINT_SIZE);
        glGetFloatv(GL_POINT_SIZE, &state.pointSize);
        glGetIntegerv(GL_POLYGON_MODE, state.polygonMode.data());
        return state;
    }
};

TEST_F(FramePassesTest, EveryPartOfTheRecordIsSetAndTheDefaultRestored)
{
    profiler_.beginFrame();
    FramePasses passes(gpuScene_, targets_, profiler_);
    const PipelineState everything{.cull = Cull::FrontFaces,
                                   .frontFace = Winding::Clockwise,
                                   .depthBias = {3.0f, 16.0f},
                                   .viewport = {2, 3, 20, 10},
                                   .scissor = {1, 1, 8, 9},
                                   .pointSizeFromShader = true,
                                   .pointSize = 4.0f,
                                   .polygonMode = PolygonMode::Lines};
    FaceAndRasterState inside;
    passes.run({.name = "everything", .target = Resource::LitImage, .state = everything},
               [&] { inside = FaceAndRasterState::read(); });
    EXPECT_EQ(inside.culling, GL_TRUE);
    EXPECT_EQ(inside.culledFace, GL_FRONT);
    EXPECT_EQ(inside.frontFace, GL_CW);
    EXPECT_EQ(inside.depthBias, GL_TRUE);
    EXPECT_EQ(inside.slopeScaledBias, 3.0f);
    EXPECT_EQ(inside.constantBias, 16.0f);
    EXPECT_EQ(inside.viewport, (std::array<GLint, 4>{2, 3, 20, 10}));
    EXPECT_EQ(inside.scissorTest, GL_TRUE);
    EXPECT_EQ(inside.scissor, (std::array<GLint, 4>{1, 1, 8, 9}));
    EXPECT_EQ(inside.pointSizeFromShader, GL_TRUE);
    EXPECT_EQ(inside.pointSize, 4.0f);
    EXPECT_EQ(inside.polygonMode[0], GL_LINE);

    // After the pass, and in a pass whose record is all zero: GL's defaults, with the viewport
    // of the whole target.
    const auto expectDefaults = [&](const FaceAndRasterState& state) {
        EXPECT_EQ(state.culling, GL_FALSE);
        EXPECT_EQ(state.culledFace, GL_BACK);
        EXPECT_EQ(state.frontFace, GL_CCW);
        EXPECT_EQ(state.depthBias, GL_FALSE);
        EXPECT_EQ(state.slopeScaledBias, 0.0f);
        EXPECT_EQ(state.viewport, (std::array<GLint, 4>{0, 0, targets_.width, targets_.height}));
        EXPECT_EQ(state.scissorTest, GL_FALSE);
        EXPECT_EQ(state.pointSizeFromShader, GL_FALSE);
        EXPECT_EQ(state.pointSize, 1.0f);
        EXPECT_EQ(state.polygonMode[0], GL_FILL);
    };
    expectDefaults(FaceAndRasterState::read());
    FaceAndRasterState zero;
    passes.run({.name = "zero", .target = Resource::LitImage}, [&] { zero = FaceAndRasterState::read(); });
    expectDefaults(zero);
    passes.finish();
    profiler_.endFrame();
}

TEST_F(FramePassesTest, APassIntoItsOwnFramebufferDrawsThereWithItsViewport)
{
    const gl::Texture2D depth("own target", GL_DEPTH_COMPONENT24, 8, 8);
    const gl::Framebuffer framebuffer("own target", {}, &depth);
    profiler_.beginFrame();
    FramePasses passes(gpuScene_, targets_, profiler_);
    GLint boundFramebuffer = 0;
    std::array<GLint, 4> viewport{};
    const Pass own{.name = "own", .framebuffer = &framebuffer, .state = {.viewport = {0, 0, 8, 8}}};
    EXPECT_EQ(passes.barrierFor(own), 0u);
    passes.run(own, [&] {
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &boundFramebuffer);
        glGetIntegerv(GL_VIEWPORT, viewport.data());
    });
    EXPECT_EQ(static_cast<GLuint>(boundFramebuffer), framebuffer.id());
    EXPECT_EQ(viewport, (std::array<GLint, 4>{0, 0, 8, 8}));
    glGetIntegerv(GL_VIEWPORT, viewport.data());
    EXPECT_EQ(viewport, (std::array<GLint, 4>{0, 0, targets_.width, targets_.height}));
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
