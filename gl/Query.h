// gl::Query: one GL query object (timer or pipeline statistics) for the pass profiler
// (render/frame/PassProfiler.h) and the tests that count primitives and fragment invocations.
#pragma once

#include <cstdint>
#include <string_view>

#include "gl/GlObject.h"

namespace manylights::gl {

namespace detail {
inline void deleteQuery(GLuint name) { glDeleteQueries(1, &name); }
}  // namespace detail

// One query object of a fixed target: GL_TIME_ELAPSED (nanoseconds of GPU time), GL_TIMESTAMP
// (used with stamp()), or a pipeline-statistics target such as
// GL_FRAGMENT_SHADER_INVOCATIONS_ARB.
class Query : public GlObject<detail::deleteQuery> {
public:
    Query() = default;
    Query(std::string_view label, GLenum target);

    void begin() const { glBeginQuery(target_, id()); }
    void end() const { glEndQuery(target_); }
    // Records the GPU time when the commands before it have completed (GL_TIMESTAMP only).
    void stamp() const { glQueryCounter(id(), GL_TIMESTAMP); }
    // Waits for the GPU and returns the result.
    std::uint64_t result() const;
    // Whether the result is there to read without waiting (GL_QUERY_RESULT_AVAILABLE).
    bool available() const;

private:
    GLenum target_ = 0;
};

// Whether the context can count fragment-shader invocations (ARB_pipeline_statistics_query,
// core in GL 4.6).
bool hasPipelineStatistics();

}  // namespace manylights::gl
