// Time and fragment-shader invocations (pipeline statistics) per pass and per frame.
//
// Two clocks, because neither is right everywhere. GL timer queries (GL_TIME_ELAPSED per
// pass, GL_TIMESTAMP per frame) are what a GPU profiler shows, but llvmpipe records them when
// it bins commands, not when its threads rasterise the tiles, so it under-reports passes with
// many draws by up to 10x. The wall clock between glFinish calls is exact on llvmpipe (the
// GPU is the CPU), but on a GPU each glFinish drains the GPU, so a frame timed that way is a
// frame no application runs. PassTiming (render/driver/DriverProfile.h) says which a frame
// gets; the driver profile picks (DriverChoices::passTiming) and --pass-timing overrides
// (docs/performance.md, "Timing on a GPU").
#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "gl/Debug.h"
#include "gl/Query.h"
#include "render/driver/DriverProfile.h"

namespace manylights {

struct PassSample {
    std::string name;
    std::optional<double> gpuMs;                       // GL_TIME_ELAPSED; absent under PassTiming::Frame
    std::optional<double> wallMs;                      // glFinish to glFinish; under PassTiming::Wall only
    std::optional<std::uint64_t> fragmentInvocations;  // absent where the driver cannot count, or under Frame
};

struct FrameSample {
    double gpuMs = 0.0;  // between GL_TIMESTAMPs at the frame's start and end
    // The frame's time on the CPU clock. Under PassTiming::Wall, from glFinish to glFinish.
    // Otherwise, for a frame issued right after the one before (back to back): from the end of
    // that frame's issue to the end of this one's, the period an application's loop sees,
    // which with a bounded number of frames in flight is the GPU's frame time when the GPU is
    // the bottleneck; for a frame issued after the GPU was drained, from its start until the
    // CPU saw the GPU finish it.
    double wallMs = 0.0;
    PassTiming timing = PassTiming::Wall;
    std::vector<PassSample> passes;
};

class PassProfiler {
public:
    // Ends the pass's queries and debug group when it goes out of scope.
    class Scope {
    public:
        Scope(PassProfiler& profiler, std::string_view name);
        ~Scope();
        Scope(const Scope&) = delete;
        Scope& operator=(const Scope&) = delete;

    private:
        PassProfiler& profiler_;
        gl::DebugGroup group_;
        std::size_t index_;
        std::chrono::steady_clock::time_point start_;
    };

    explicit PassProfiler(PassTiming timing = PassTiming::Wall);

    PassTiming timing() const { return timing_; }

    // How often a wait for the GPU calls the wait hook.
    static constexpr std::chrono::milliseconds kWaitHookInterval{10};
    // Called after every pass and, while a wait for the GPU around a pass or a frame lasts
    // (under PassTiming::Wall), every kWaitHookInterval: the viewer reads its input there, so
    // that it knows when a key went down or up to within that much even in a frame of seconds
    // (issue 48, docs/viewer.md "Controls"). The hook must not issue GL commands. Empty: none,
    // and the waits are plain glFinish calls.
    void setWaitHook(std::function<void()> hook) { waitHook_ = std::move(hook); }

    void beginFrame();
    // Ends the frame's queries without waiting for them: its sample comes out of
    // takeOldestFrame.
    void endFrameQueued();
    // Ends the frame and waits for its sample; no earlier frame may be pending.
    FrameSample endFrame();
    // The sample of the oldest frame ended and not yet taken: with `wait`, once the GPU has run
    // it; without, only if it already has. nullopt when none is pending (or, without `wait`,
    // none is done).
    std::optional<FrameSample> takeOldestFrame(bool wait);
    std::size_t framesPending() const { return pending_.size(); }

    [[nodiscard]] Scope pass(std::string_view name) { return Scope(*this, name); }
    // The scopes opened since beginFrame (endFrame sums the scopes of one name into one
    // PassSample).
    std::size_t scopesThisFrame() const { return current_.passCount; }

private:
    struct PassQueries {
        std::string name;
        gl::Query time;
        gl::Query invocations;
        double wallMs = 0.0;
    };
    // One frame's queries, reused once its sample is taken.
    struct FrameQueries {
        PassTiming timing = PassTiming::Wall;
        gl::Query start;
        gl::Query end;
        std::vector<PassQueries> passes;
        std::size_t passCount = 0;
        std::chrono::steady_clock::time_point wallStart;
        std::optional<double> wallMs;  // known at its end under Wall, or when issued back to back
    };
    PassQueries& nextPass(std::string_view name);
    // Waits until the GPU has run every command issued: glFinish, or with a wait hook, a fence
    // waited on in steps of kWaitHookInterval with the hook called between them.
    void finishGpu() const;
    FrameQueries freshFrame();
    FrameSample sampleOf(const FrameQueries& frame) const;

    PassTiming timing_;
    std::function<void()> waitHook_;
    bool countInvocations_;
    bool inPass_ = false;  // GL allows one active time query: passes do not nest
    FrameQueries current_;
    std::deque<FrameQueries> pending_;  // ended, oldest first
    std::vector<FrameQueries> spare_;   // taken, for reuse
    // When the last frame's issue ended, while no wait has drained the frames since.
    std::optional<std::chrono::steady_clock::time_point> lastIssueEnd_;
};

}  // namespace manylights
