#include "gl/Buffer.h"

#include <string>
#include <utility>

#include "core/Error.h"
#include "gl/Debug.h"

namespace manylights::gl {

namespace {
bool failNextStorage = false;  // Buffer::failNextStorageForTesting
}  // namespace

void Buffer::failNextStorageForTesting() { failNextStorage = true; }

Buffer::Buffer(std::string_view label, std::size_t bytes, const void* data, GLbitfield flags)
    : GlObject(detail::createName(glCreateBuffers)), size_(bytes)
{
    setLabel(GL_BUFFER, id(), label);
    const std::string what = std::to_string(bytes) + " bytes for the buffer '" + std::string(label) + "'";
    if (std::exchange(failNextStorage, false))
        throwOutOfMemory(what);
    // Zero-sized storage is an error in GL; an empty buffer still gets one byte so that it
    // can be bound (a scene without local lights binds an empty light list).
    glNamedBufferStorage(id(), static_cast<GLsizeiptr>(bytes > 0 ? bytes : 1), bytes > 0 ? data : nullptr, flags);
    throwIfOutOfMemory(what);
}

void Buffer::update(std::size_t offset, std::size_t bytes, const void* data)
{
    ML_ASSERT(offset + bytes <= size_);
    if (bytes > 0)
        counted(glNamedBufferSubData, id(), static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
}

void Buffer::clearToZero(std::size_t bytes)
{
    ML_ASSERT(bytes <= size_ && bytes % 4 == 0);
    const GLuint zero = 0;
    if (bytes > 0)
        glClearNamedBufferSubData(id(), GL_R32UI, 0, static_cast<GLsizeiptr>(bytes), GL_RED_INTEGER, GL_UNSIGNED_INT,
                                  &zero);
}

void Buffer::bindBase(GLenum target, GLuint index) const { counted(glBindBufferBase, target, index, id()); }

void Buffer::bindRange(GLenum target, GLuint index, std::size_t offset, std::size_t bytes) const
{
    counted(glBindBufferRange, target, index, id(), static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes));
}

void Buffer::copyTo(const Buffer& to, std::size_t bytes) const
{
    ML_ASSERT(bytes <= size_ && bytes <= to.size_);
    if (bytes > 0)
        glCopyNamedBufferSubData(id(), to.id(), 0, 0, static_cast<GLsizeiptr>(bytes));
}

namespace {
std::uint64_t synchronousReadCount = 0;  // Buffer::synchronousReads
}  // namespace

std::uint64_t Buffer::synchronousReads() { return synchronousReadCount; }

const void* Buffer::mapForReading()
{
    constexpr GLbitfield kAccess = GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
    const void* data = glMapNamedBufferRange(id(), 0, static_cast<GLsizeiptr>(size_ > 0 ? size_ : 1), kAccess);
    ML_ASSERT(data);
    return data;
}

void Buffer::read(std::size_t offset, std::size_t bytes, void* data) const
{
    ML_ASSERT(offset + bytes <= size_);
    ++synchronousReadCount;
    if (bytes > 0)
        glGetNamedBufferSubData(id(), static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
}

}  // namespace manylights::gl
