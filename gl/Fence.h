// gl::Fence: a GL sync object (glFenceSync) that says when the GPU has run every command issued
// before it, so that the CPU can read what those commands wrote without draining the GPU
// (render/frame/PassProfiler.h and render/culling/ClusterLists.h read a frame's results a frame
// or two late behind one).
#pragma once

#include <chrono>

#include <epoxy/gl.h>

namespace manylights::gl {

class Fence {
public:
    Fence() = default;
    ~Fence() { reset(); }
    Fence(const Fence&) = delete;
    Fence& operator=(const Fence&) = delete;
    Fence(Fence&& other) noexcept;
    Fence& operator=(Fence&& other) noexcept;

    // A fence after every command issued so far (replacing the one held).
    static Fence afterIssuedCommands();

    explicit operator bool() const { return sync_ != nullptr; }
    // Whether the GPU has passed the fence; does not wait. Flushes the commands before it, so
    // that a fence polled in a loop is signalled in the end.
    bool signalled() const;
    // Waits until the GPU has passed the fence.
    void wait() const;
    // Waits until the GPU has passed the fence or `timeout` has gone by, whichever is first;
    // whether it has passed.
    bool waitFor(std::chrono::nanoseconds timeout) const;

private:
    void reset();
    GLsync sync_ = nullptr;
};

}  // namespace manylights::gl
