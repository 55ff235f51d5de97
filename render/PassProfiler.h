// GPU time (GL_TIME_ELAPSED) and fragment-shader invocations (pipeline statistics) per pass,
// and GPU time per frame (GL_TIMESTAMP at its start and end).
#pragma once

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
    double gpuMs = 0.0;
    std::optional<std::uint64_t> fragmentInvocations;  // absent where the driver cannot count
};

struct FrameSample {
    double gpuMs = 0.0;
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
    };

    PassProfiler();

    void beginFrame();
    // Waits for the frame's queries and returns its sample.
    FrameSample endFrame();
    [[nodiscard]] Scope pass(std::string_view name) { return Scope(*this, name); }

private:
    struct PassQueries {
        std::string name;
        gl::Query time;
        gl::Query invocations;
    };
    PassQueries& nextPass(std::string_view name);

    bool countInvocations_;
    bool inPass_ = false;  // GL allows one active time query: passes do not nest
    gl::Query frameStart_;
    gl::Query frameEnd_;
    std::vector<PassQueries> passes_;  // reused from frame to frame
    std::size_t passesThisFrame_ = 0;
};

}  // namespace manylights
