// Ownership of one GL object name: created by the wrapper's constructor, deleted by the
// destructor, moved but never copied (Magnum's GL::Buffer model). The wrappers below derive
// from it with the matching delete function.
#pragma once

#include <epoxy/gl.h>

#include <string_view>
#include <utility>

#include "gl/CallTally.h"

namespace manylights::gl {

// Attaches a human-readable name that debuggers (RenderDoc) and the debug callback show.
void setLabel(GLenum identifier, GLuint name, std::string_view label);

namespace detail {
// A new object's name from a glCreate* function (DSA: created, not bound): `create` takes
// `before` (a texture's target), then the count and where to write the name.
template <typename Create, typename... Before>
GLuint createName(Create create, Before... before)
{
    GLuint name = 0;
    create(before..., 1, &name);
    return name;
}
}  // namespace detail

template <void (*Delete)(GLuint)>
class GlObject {
public:
    GlObject() = default;
    explicit GlObject(GLuint name) : name_(name) {}
    ~GlObject() { reset(); }
    GlObject(const GlObject&) = delete;
    GlObject& operator=(const GlObject&) = delete;
    GlObject(GlObject&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
    GlObject& operator=(GlObject&& other) noexcept
    {
        if (this != &other) {
            reset();
            name_ = std::exchange(other.name_, 0);
        }
        return *this;
    }

    GLuint id() const { return name_; }
    explicit operator bool() const { return name_ != 0; }

private:
    void reset()
    {
        if (name_ != 0)
            Delete(name_);
        name_ = 0;
    }
    GLuint name_ = 0;
};

}  // namespace manylights::gl
