// Small results of the GPU read on the CPU without stalling it (issue 41: no stalls): after a
// frame's commands, a buffer's first bytes are copied into one of a ring of persistently
// mapped buffers behind a fence, with a record of what the CPU needs to judge them; a frame
// or two later (frames issued back to back) or at once (a frame waited for), the oldest copy
// is read, waiting for its fence only where the GPU has not passed it yet. The copies are
// reused: a ring of as many as frames in flight, made once.
#pragma once

#include <cstddef>
#include <cstring>
#include <deque>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "gl/Buffer.h"
#include "gl/Fence.h"

namespace manylights {

// Copies of a `Contents` (the first sizeof(Contents) bytes of the source buffer, as plain bytes),
// each with a `Record`.
template <typename Contents, typename Record>
class ReadbackRing {
    static_assert(std::is_trivially_copyable_v<Contents>, "read back as bytes");

public:
    // The copies' buffers are labelled `label`.
    explicit ReadbackRing(std::string label) : label_(std::move(label)) {}

    // After the commands that write `source` (shader writes included: a barrier orders the copy
    // after them): copies its first bytes, fenced, with `record`.
    void push(const gl::Buffer& source, const Record& record)
    {
        Copy copy;
        if (!spare_.empty()) {
            copy = std::move(spare_.back());
            spare_.pop_back();
        } else {
            copy.buffer = gl::Buffer(label_, sizeof(Contents), nullptr,
                                     GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT);
            copy.mapped = copy.buffer.mapForReading();
        }
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        source.copyTo(copy.buffer, sizeof(Contents));
        copy.fence = gl::Fence::afterIssuedCommands();
        copy.record = record;
        pending_.push_back(std::move(copy));
    }

    // Copies pushed and not yet read.
    std::size_t pending() const { return pending_.size(); }

    // The oldest copy into `out` and its record, after waiting for its fence; pending() must not
    // be 0.
    Record readOldest(Contents& out)
    {
        Copy& copy = pending_.front();
        copy.fence.wait();
        std::memcpy(&out, copy.mapped, sizeof(Contents));
        Record record = std::move(copy.record);
        spare_.push_back(std::move(copy));
        pending_.pop_front();
        return record;
    }

private:
    struct Copy {
        gl::Buffer buffer;  // persistently mapped
        const void* mapped = nullptr;
        gl::Fence fence;
        Record record{};
    };
    std::string label_;
    std::deque<Copy> pending_;  // oldest first
    std::vector<Copy> spare_;   // read, for reuse
};

}  // namespace manylights
