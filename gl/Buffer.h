// gl::Buffer: a buffer object with immutable storage (DSA), owned and labelled for the debug
// output; the scene, the light grid and the passes keep their GPU data in these.
#pragma once

#include <cstddef>
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

private:
    std::size_t size_ = 0;
};

}  // namespace manylights::gl
