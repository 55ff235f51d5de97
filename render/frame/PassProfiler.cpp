#include "render/frame/PassProfiler.h"

#include <algorithm>

#include "core/Error.h"

namespace manylights {

namespace {
constexpr double kNanosecondsPerMs = 1.0e6;

double millisecondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}
}  // namespace

PassProfiler::PassProfiler()
    : countInvocations_(gl::hasPipelineStatistics()),
      frameStart_("frame start", GL_TIMESTAMP),
      frameEnd_("frame end", GL_TIMESTAMP)
{
}

void PassProfiler::beginFrame()
{
    passesThisFrame_ = 0;
    glFinish();
    frameStartTime_ = std::chrono::steady_clock::now();
    frameStart_.stamp();
}

PassProfiler::PassQueries& PassProfiler::nextPass(std::string_view name)
{
    if (passesThisFrame_ == passes_.size())
        passes_.push_back({std::string(name), gl::Query(std::string(name) + " time", GL_TIME_ELAPSED),
                           countInvocations_
                               ? gl::Query(std::string(name) + " invocations", GL_FRAGMENT_SHADER_INVOCATIONS_ARB)
                               : gl::Query()});
    PassQueries& queries = passes_[passesThisFrame_++];
    queries.name = name;
    return queries;
}

PassProfiler::Scope::Scope(PassProfiler& profiler, std::string_view name)
    : profiler_(profiler), group_(name), index_(profiler.passesThisFrame_)
{
    ML_ASSERT(!profiler_.inPass_);
    profiler_.inPass_ = true;
    PassQueries& queries = profiler_.nextPass(name);
    glFinish();
    start_ = std::chrono::steady_clock::now();
    queries.time.begin();
    if (queries.invocations)
        queries.invocations.begin();
}

PassProfiler::Scope::~Scope()
{
    PassQueries& queries = profiler_.passes_[index_];
    queries.time.end();
    if (queries.invocations)
        queries.invocations.end();
    glFinish();
    queries.wallMs = millisecondsSince(start_);
    profiler_.inPass_ = false;
}

FrameSample PassProfiler::endFrame()
{
    frameEnd_.stamp();
    glFinish();
    FrameSample sample;
    sample.wallMs = millisecondsSince(frameStartTime_);
    sample.gpuMs = static_cast<double>(frameEnd_.result() - frameStart_.result()) / kNanosecondsPerMs;
    for (std::size_t i = 0; i < passesThisFrame_; ++i) {
        const PassQueries& queries = passes_[i];
        // A pass that runs once per light batch (render/culling/LightBatches.h) is one entry: the
        // sum of its runs, in the place of its first.
        auto pass = std::find_if(sample.passes.begin(), sample.passes.end(),
                                 [&](const PassSample& earlier) { return earlier.name == queries.name; });
        if (pass == sample.passes.end()) {
            PassSample first;
            first.name = queries.name;
            sample.passes.push_back(std::move(first));
            pass = sample.passes.end() - 1;
        }
        pass->gpuMs += static_cast<double>(queries.time.result()) / kNanosecondsPerMs;
        pass->wallMs += queries.wallMs;
        if (queries.invocations)
            pass->fragmentInvocations = pass->fragmentInvocations.value_or(0) + queries.invocations.result();
    }
    return sample;
}

}  // namespace manylights
