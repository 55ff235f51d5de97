// Passes as records. Each pass of a frame is a short record: its name, the target it draws
// into with the pipeline state it draws with (or none: a compute or CPU pass), and the frame
// resources it reads and writes. FramePasses::run derives the rest from the record: the
// profiler's scope (consecutive passes of one name share one, and the profiler sums a name's
// scopes: a technique's light batches are one timed pass), the bound target and inputs, the GL
// state, and the memory barriers between passes. A technique's render() is then a list of
// passes, each with the draw or dispatch that is its own. Not a frame graph: the frame is a
// fixed sequence, run in the order written.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

#include <epoxy/gl.h>

#include "render/frame/FrameTargets.h"
#include "render/frame/PassProfiler.h"
#include "render/programs/PipelineState.h"

namespace manylights {

class GpuScene;

// What passes share within a frame, as bits of a mask.
enum class Resource : std::uint8_t {
    None = 0,
    LitImage = 1,  // FrameTargets::lit (and the depth it is drawn with)
    // FrameTargets::gbuffer, the scene's depth, and what SSAO computes from them (render/effects/Ssao.h)
    GBuffer = 2,
    // a cluster grid's buffers (render/culling/ClusterGrid.h) and its light lists (render/culling/ClusterLists.h)
    LightGrid = 4,
    WorkCounts = 8,    // the work-counting images and counters (--count-work)
    ShadowPages = 16,  // the shadow-page pool's marks and tables (render/shadows/ShadowPool.h)
};
inline constexpr int kResourceKinds = 5;

constexpr Resource operator|(Resource a, Resource b)
{
    return static_cast<Resource>(static_cast<std::uint8_t>(a) | static_cast<std::uint8_t>(b));
}
constexpr bool contains(Resource set, Resource one)
{
    return (static_cast<std::uint8_t>(set) & static_cast<std::uint8_t>(one)) != 0;
}

struct Pass {
    std::string_view name;
    // Draws: bound as the framebuffer (LitImage or GBuffer), with `state` applied. None: the
    // pass dispatches compute work or runs on the CPU, and `state` does not apply.
    Resource target = Resource::None;
    // Draws into this framebuffer instead of a target of the frame (shadow maps, the display
    // pass's images), with `state` applied. One of another size than the frame names its
    // viewport in `state`.
    const gl::Framebuffer* framebuffer = nullptr;
    PipelineState state{};
    // Read by texture fetches. GBuffer binds the G-buffer's targets for reading and the
    // scene's depth at SCENE_DEPTH_UNIT.
    Resource sampled = Resource::None;
    // Loaded and stored as images. LitImage binds the lit image at LIT_IMAGE_UNIT.
    Resource images = Resource::None;
    // Read or written as storage buffers (the pass binds its own buffers).
    Resource storage = Resource::None;
    // Read by buffer commands: copied from, or read back.
    Resource transfers = Resource::None;
    // Read as the parameters of an indirect draw or dispatch.
    Resource indirect = Resource::None;
    // Of the images and storage buffers, those the pass writes (stores, atomics, clears):
    // the next pass that uses them waits for the writes.
    Resource writes = Resource::None;
};

class FramePasses {
public:
    // One frame's passes. The lit image and the depth have been cleared (drawn into).
    FramePasses(const GpuScene& scene, FrameTargets& targets, PassProfiler& profiler);
    ~FramePasses();
    FramePasses(const FramePasses&) = delete;
    FramePasses& operator=(const FramePasses&) = delete;

    // Runs `pass`: its scope, its barrier, its target, inputs and state; then `work` (the
    // draws or dispatches), after binding the scene (frame uniforms, lights, vertices).
    template <typename Work>
    void run(const Pass& pass, Work&& work)
    {
        begin(pass);
        work();
        end(pass);
    }
    // Closes the last timed pass and waits for the passes' writes: before the CPU reads
    // resources back, or code outside the passes uses them.
    void finish();
    // The viewer's wireframe: the passes that draw into the frame's lit image draw their
    // polygons as `mode` says, whatever their records say (forward's meshes; the G-buffer, the
    // shadow maps and the display pass stay filled).
    void setLitImagePolygonMode(PolygonMode mode) { litImagePolygonMode_ = mode; }

    const GpuScene& scene() const { return scene_; }
    FrameTargets& targets() { return targets_; }

    // The memory barrier `pass` would wait on if it ran now (0: none); run() issues it.
    GLbitfield barrierFor(const Pass& pass) const;

private:
    void begin(const Pass& pass);
    void end(const Pass& pass);
    static bool draws(const Pass& pass) { return pass.target != Resource::None || pass.framebuffer != nullptr; }

    // Per resource: the barrier bits its last incoherent writes (image stores, storage writes)
    // still need for each kind of access, and whether draws used it since the last barrier
    // (llvmpipe runs compute work and buffer clears at once but queues draws: a compute pass
    // after draws that used its resource must wait for them).
    struct ResourceState {
        GLbitfield unmadeVisible = 0;
        bool usedByQueuedDraws = false;
    };
    std::array<ResourceState, kResourceKinds> states_{};
    ResourceState& state(int bit) { return states_[static_cast<std::size_t>(bit)]; }

    const GpuScene& scene_;
    FrameTargets& targets_;
    PassProfiler& profiler_;
    std::optional<PassProfiler::Scope> scope_;
    std::string_view scopeName_;
    PolygonMode litImagePolygonMode_ = PolygonMode::Fill;
};

}  // namespace manylights
