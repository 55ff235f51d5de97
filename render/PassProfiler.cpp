#include "render/PassProfiler.h"

#include "scene/Error.h"

namespace manylights {

namespace {
constexpr double kNanosecondsPerMs = 1.0e6;
}

PassProfiler::PassProfiler()
    : countInvocations_(gl::hasPipelineStatistics()),
      frameStart_("frame start", GL_TIMESTAMP),
      frameEnd_("frame end", GL_TIMESTAMP)
{
}

void PassProfiler::beginFrame()
{
    passesThisFrame_ = 0;
    frameStart_.stamp();
}

PassProfiler::PassQueries& PassProfiler::nextPass(std::string_view name)
{
    if (passesThisFrame_ == passes_.size())
        passes_.push_back({std::string(name), gl::Query(std::string(name) + " time", GL_TIME_ELAPSED),
                           countInvocations_ ? gl::Query(std::string(name) + " invocations",
                                                         GL_FRAGMENT_SHADER_INVOCATIONS_ARB)
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
    profiler_.inPass_ = false;
}

FrameSample PassProfiler::endFrame()
{
    frameEnd_.stamp();
    FrameSample sample;
    sample.gpuMs = static_cast<double>(frameEnd_.result() - frameStart_.result()) / kNanosecondsPerMs;
    for (std::size_t i = 0; i < passesThisFrame_; ++i) {
        const PassQueries& queries = passes_[i];
        PassSample pass;
        pass.name = queries.name;
        pass.gpuMs = static_cast<double>(queries.time.result()) / kNanosecondsPerMs;
        if (queries.invocations)
            pass.fragmentInvocations = queries.invocations.result();
        sample.passes.push_back(std::move(pass));
    }
    return sample;
}

}  // namespace manylights
