#include "gl/Fence.h"

#include <algorithm>
#include <cstdint>
#include <utility>

#include "core/Error.h"

namespace manylights::gl {

Fence::Fence(Fence&& other) noexcept : sync_(std::exchange(other.sync_, nullptr)) {}

Fence& Fence::operator=(Fence&& other) noexcept
{
    if (this != &other) {
        reset();
        sync_ = std::exchange(other.sync_, nullptr);
    }
    return *this;
}

Fence Fence::afterIssuedCommands()
{
    Fence fence;
    fence.sync_ = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    return fence;
}

bool Fence::signalled() const
{
    ML_ASSERT(sync_);
    const GLenum status = glClientWaitSync(sync_, GL_SYNC_FLUSH_COMMANDS_BIT, 0);
    ML_ASSERT(status != GL_WAIT_FAILED);
    return status == GL_ALREADY_SIGNALED || status == GL_CONDITION_SATISFIED;
}

void Fence::wait() const
{
    ML_ASSERT(sync_);
    // GL_TIMEOUT_IGNORED is not a valid timeout for glClientWaitSync: wait in steps of a second.
    constexpr GLuint64 kSecond = 1'000'000'000;
    GLenum status = GL_TIMEOUT_EXPIRED;
    while (status == GL_TIMEOUT_EXPIRED)
        status = glClientWaitSync(sync_, GL_SYNC_FLUSH_COMMANDS_BIT, kSecond);
    ML_ASSERT(status != GL_WAIT_FAILED);
}

bool Fence::waitFor(std::chrono::nanoseconds timeout) const
{
    ML_ASSERT(sync_);
    const auto nanoseconds = static_cast<GLuint64>(std::max<std::chrono::nanoseconds::rep>(0, timeout.count()));
    const GLenum status = glClientWaitSync(sync_, GL_SYNC_FLUSH_COMMANDS_BIT, nanoseconds);
    ML_ASSERT(status != GL_WAIT_FAILED);
    return status == GL_ALREADY_SIGNALED || status == GL_CONDITION_SATISFIED;
}

void Fence::reset()
{
    if (sync_)
        glDeleteSync(sync_);
    sync_ = nullptr;
}

}  // namespace manylights::gl
