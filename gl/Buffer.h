// gl::Buffer: a buffer object with immutable storage (DSA), owned and labelled for the debug
// output; the scene, the light grid and the passes keep their GPU data in these.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "gl/GlObject.h"

namespace manylights::gl {

namespace detail {
inline void deleteBuffer(GLuint name) { glDeleteBuffers(1, &name); }
}  // namespace detail

// An immutable-storage buffer (glNamedBufferStorage), updated with glNamedBufferSubData when
// created with dynamic storage.
class Buffer : public GlObject<detail::deleteBuffer> {
public:
    Buffer() = default;
    Buffer(std::string_view label, std::size_t bytes, const void* data, GLbitfield flags = GL_DYNAMIC_STORAGE_BIT);

    template <typename T>
    static Buffer fromSpan(std::string_view label, std::span<const T> data, GLbitfield flags = GL_DYNAMIC_STORAGE_BIT)
    {
        return Buffer(label, data.size_bytes(), data.data(), flags);
    }

    void update(std::size_t offset, std::size_t bytes, const void* data);
    // Zeroes the first `bytes` (a multiple of 4) on the GPU (glClearNamedBufferSubData), as a
    // GL command: shaders of later commands see the zeros.
    void clearToZero(std::size_t bytes);
    void bindBase(GLenum target, GLuint index) const;
    // Binds `bytes` from `offset` to the indexed `target` (glBindBufferRange).
    void bindRange(GLenum target, GLuint index, std::size_t offset, std::size_t bytes) const;
    // Copies the first `bytes` into `to` on the GPU (glCopyNamedBufferSubData).
    void copyTo(const Buffer& to, std::size_t bytes) const;
    // Reads `bytes` from `offset` back to the CPU, waiting for the commands that write them.
    void read(std::size_t offset, std::size_t bytes, void* data) const;
    // Makes this the buffer glDispatchComputeIndirect reads its workgroup counts from.
    void bindAsDispatchIndirect() const { glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, id()); }
    std::size_t size() const { return size_; }
    // Maps the whole buffer for reading, persistently and coherently (it must have been made
    // with GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT), and returns where its
    // bytes are: what the GPU wrote there is visible once a fence after the writes has signalled
    // (gl::Fence), with no read call that could wait for the GPU.
    const void* mapForReading();
    // Buffer::read calls so far, in this process: the synchronous read-backs, each of which may
    // wait for the GPU to drain. Tests count them.
    static std::uint64_t synchronousReads();

    // Test hook: the next Buffer made fails as though the driver had answered its storage
    // request with GL_OUT_OF_MEMORY, whatever its size. The tests of the out-of-memory path
    // use it on every driver: a 64-bit GPU driver may hand out a terabyte of virtual storage
    // that a request for "more than the machine has" cannot count on being refused.
    static void failNextStorageForTesting();

private:
    std::size_t size_ = 0;
};

// Uploads `data` to the start of `buffer`, first replacing the buffer with a larger one when the
// data does not fit (with half as much again to grow into, so that a slowly growing list does
// not reallocate every frame): per-frame lists of the CPU's.
template <typename T>
void uploadGrowing(Buffer& buffer, std::string_view label, std::span<const T> data)
{
    if (!buffer || buffer.size() < data.size_bytes())
        buffer = Buffer(label, data.size_bytes() + data.size_bytes() / 2, nullptr);
    buffer.update(0, data.size_bytes(), data.data());
}

}  // namespace manylights::gl
