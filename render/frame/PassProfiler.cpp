#include "render/frame/PassProfiler.h"

#include <algorithm>
#include <utility>

#include "core/Error.h"
#include "gl/Fence.h"

namespace manylights {

namespace {
constexpr double kNanosecondsPerMs = 1.0e6;

double millisecondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}
}  // namespace

PassProfiler::PassProfiler(PassTiming timing) : timing_(timing), countInvocations_(gl::hasPipelineStatistics())
{
    current_ = freshFrame();
}

void PassProfiler::finishGpu() const
{
    if (!waitHook_) {
        glFinish();
        return;
    }
    const gl::Fence fence = gl::Fence::afterIssuedCommands();
    while (!fence.waitFor(kWaitHookInterval))
        waitHook_();
}

PassProfiler::FrameQueries PassProfiler::freshFrame()
{
    if (!spare_.empty()) {
        FrameQueries frame = std::move(spare_.back());
        spare_.pop_back();
        return frame;
    }
    FrameQueries frame;
    frame.start = gl::Query("frame start", GL_TIMESTAMP);
    frame.end = gl::Query("frame end", GL_TIMESTAMP);
    return frame;
}

void PassProfiler::beginFrame()
{
    current_.timing = timing_;
    current_.passCount = 0;
    current_.wallMs.reset();
    if (timing_ == PassTiming::Wall) {
        finishGpu();
        current_.wallStart = std::chrono::steady_clock::now();
    } else {
        // Back to back: this frame's time runs from the end of the last one's issue.
        current_.wallStart = lastIssueEnd_.value_or(std::chrono::steady_clock::now());
    }
    current_.start.stamp();
}

PassProfiler::PassQueries& PassProfiler::nextPass(std::string_view name)
{
    std::vector<PassQueries>& passes = current_.passes;
    if (current_.passCount == passes.size()) {
        const bool timed = current_.timing != PassTiming::Frame;
        passes.push_back({std::string(name),
                          timed ? gl::Query(std::string(name) + " time", GL_TIME_ELAPSED) : gl::Query(),
                          timed && countInvocations_
                              ? gl::Query(std::string(name) + " invocations", GL_FRAGMENT_SHADER_INVOCATIONS_ARB)
                              : gl::Query()});
    }
    PassQueries& queries = passes[current_.passCount++];
    queries.name = name;
    // A frame's queries may be reused under another timing: a Frame frame made none.
    if (current_.timing != PassTiming::Frame && !queries.time) {
        queries.time = gl::Query(std::string(name) + " time", GL_TIME_ELAPSED);
        if (countInvocations_)
            queries.invocations = gl::Query(std::string(name) + " invocations", GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
    }
    return queries;
}

PassProfiler::Scope::Scope(PassProfiler& profiler, std::string_view name)
    : profiler_(profiler), group_(name), index_(profiler.current_.passCount)
{
    ML_ASSERT(!profiler_.inPass_);
    profiler_.inPass_ = true;
    PassQueries& queries = profiler_.nextPass(name);
    const PassTiming timing = profiler_.current_.timing;
    if (timing == PassTiming::Wall)
        profiler_.finishGpu();
    start_ = std::chrono::steady_clock::now();
    if (timing != PassTiming::Frame) {
        queries.time.begin();
        if (queries.invocations)
            queries.invocations.begin();
    }
}

PassProfiler::Scope::~Scope()
{
    PassQueries& queries = profiler_.current_.passes[index_];
    const PassTiming timing = profiler_.current_.timing;
    if (timing != PassTiming::Frame) {
        queries.time.end();
        if (queries.invocations)
            queries.invocations.end();
    }
    if (timing == PassTiming::Wall) {
        profiler_.finishGpu();
        queries.wallMs = millisecondsSince(start_);
    }
    profiler_.inPass_ = false;
    if (profiler_.waitHook_)
        profiler_.waitHook_();
}

void PassProfiler::endFrameQueued()
{
    ML_ASSERT(!inPass_);
    current_.end.stamp();
    if (current_.timing == PassTiming::Wall) {
        finishGpu();
        current_.wallMs = millisecondsSince(current_.wallStart);
        lastIssueEnd_.reset();
    } else {
        // Issued: the GPU runs it while the CPU goes on. Its time is the period from the last
        // frame's issue when that one was issued right before it (beginFrame); otherwise it is
        // measured when the CPU waits for it (takeOldestFrame).
        const auto now = std::chrono::steady_clock::now();
        if (lastIssueEnd_)
            current_.wallMs = std::chrono::duration<double, std::milli>(now - current_.wallStart).count();
        lastIssueEnd_ = now;
        glFlush();  // the GPU starts on it now, not when the next frame's commands fill a batch
    }
    pending_.push_back(std::move(current_));
    current_ = freshFrame();
}

FrameSample PassProfiler::endFrame()
{
    ML_ASSERT(pending_.empty());
    endFrameQueued();
    std::optional<FrameSample> sample = takeOldestFrame(true);
    ML_ASSERT(sample);
    return std::move(*sample);
}

std::optional<FrameSample> PassProfiler::takeOldestFrame(bool wait)
{
    if (pending_.empty())
        return std::nullopt;
    FrameQueries& frame = pending_.front();
    // The end timestamp is the frame's last query: when it is there, so are the others.
    const bool done = frame.end.available();
    if (!done && !wait)
        return std::nullopt;
    if (!done) {
        frame.end.result();  // waits for the GPU
        // The GPU is drained up to this frame: the next one issued starts a new run.
        if (pending_.size() == 1)
            lastIssueEnd_.reset();
    }
    // A frame not issued back to back ends when the CPU sees the GPU finish it (no later than now).
    if (!frame.wallMs)
        frame.wallMs = millisecondsSince(frame.wallStart);
    FrameSample sample = sampleOf(frame);
    spare_.push_back(std::move(frame));
    pending_.pop_front();
    return sample;
}

FrameSample PassProfiler::sampleOf(const FrameQueries& frame) const
{
    FrameSample sample;
    sample.timing = frame.timing;
    sample.wallMs = frame.wallMs.value_or(0.0);
    sample.gpuMs = static_cast<double>(frame.end.result() - frame.start.result()) / kNanosecondsPerMs;
    for (std::size_t i = 0; i < frame.passCount; ++i) {
        const PassQueries& queries = frame.passes[i];
        // A pass that runs once per light batch (render/programs/LightBatches.h) is one entry: the
        // sum of its runs, in the place of its first.
        auto pass = std::find_if(sample.passes.begin(), sample.passes.end(),
                                 [&](const PassSample& earlier) { return earlier.name == queries.name; });
        if (pass == sample.passes.end()) {
            PassSample first;
            first.name = queries.name;
            sample.passes.push_back(std::move(first));
            pass = sample.passes.end() - 1;
        }
        if (frame.timing != PassTiming::Frame)
            pass->gpuMs = pass->gpuMs.value_or(0.0) + static_cast<double>(queries.time.result()) / kNanosecondsPerMs;
        if (frame.timing == PassTiming::Wall)
            pass->wallMs = pass->wallMs.value_or(0.0) + queries.wallMs;
        if (frame.timing != PassTiming::Frame && queries.invocations)
            pass->fragmentInvocations = pass->fragmentInvocations.value_or(0) + queries.invocations.result();
    }
    return sample;
}

}  // namespace manylights
