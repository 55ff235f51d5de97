// Time and fragment-shader invocations (pipeline statistics) per pass and per frame.
//
// Two clocks, because neither is right everywhere. GL timer queries (GL_TIME_ELAPSED per
// pass, GL_TIMESTAMP per frame) are what a GPU profiler shows, but llvmpipe records them when
// it bins commands, not when its threads rasterise the tiles, so it under-reports passes with
// many draws by up to 10x. The wall clock between glFinish calls is exact on llvmpipe (the
// GPU is the CPU) and on a GPU adds only the submission latency. frame_ms uses the wall
// clock; the timer queries are reported beside it.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "gl/Debug.h"
#include "gl/Query.h"

namespace manylights {

struct PassSample {
    std::string name;
    double gpuMs = 0.0;                                // GL_TIME_ELAPSED
    double wallMs = 0.0;                               // wall clock from glFinish to glFinish
    std::optional<std::uint64_t> fragmentInvocations;  // absent where the driver cannot count
};

struct FrameSample {
    double gpuMs = 0.0;   // between GL_TIMESTAMPs at the frame's start and end
    double wallMs = 0.0;  // wall clock from glFinish to glFinish
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

    PassProfiler();

    void beginFrame();
    // Waits for the frame's queries and returns its sample.
    FrameSample endFrame();
    [[nodiscard]] Scope pass(std::string_view name) { return Scope(*this, name); }
    // The scopes opened since beginFrame, each with a glFinish at either end (endFrame sums
    // the scopes of one name into one PassSample).
    std::size_t scopesThisFrame() const { return passesThisFrame_; }

private:
    struct PassQueries {
        std::string name;
        gl::Query time;
        gl::Query invocations;
        double wallMs = 0.0;
    };
    PassQueries& nextPass(std::string_view name);

    bool countInvocations_;
    bool inPass_ = false;  // GL allows one active time query: passes do not nest
    gl::Query frameStart_;
    gl::Query frameEnd_;
    std::vector<PassQueries> passes_;  // reused from frame to frame
    std::size_t passesThisFrame_ = 0;
    std::chrono::steady_clock::time_point frameStartTime_;
};

}  // namespace manylights
