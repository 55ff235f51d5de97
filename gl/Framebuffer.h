// gl::Framebuffer: a framebuffer object (DSA) with its attachments, clears and draw buffers,
// owned and labelled: every pass that renders into textures renders through one.
#pragma once

#include <initializer_list>
#include <span>
#include <string_view>
#include <vector>

#include "gl/GlObject.h"
#include "gl/Texture.h"

namespace manylights::gl {

namespace detail {
inline void deleteFramebuffer(GLuint name) { glDeleteFramebuffers(1, &name); }
}  // namespace detail

class Framebuffer : public GlObject<detail::deleteFramebuffer> {
public:
    Framebuffer() = default;
    // Colour attachments in order (GL_COLOR_ATTACHMENT0 + i, all enabled as draw buffers) and
    // an optional depth or depth-stencil texture. Asserts completeness.
    Framebuffer(std::string_view label, std::span<const Texture2D* const> colour, const Texture2D* depth);
    Framebuffer(std::string_view label, std::initializer_list<const Texture2D*> colour, const Texture2D* depth)
        : Framebuffer(label, std::span<const Texture2D* const>(colour.begin(), colour.size()), depth)
    {
    }
    // A depth-only framebuffer whose attachment changes between passes (attachDepthLayer):
    // no colour buffers, nothing attached yet.
    explicit Framebuffer(std::string_view label);
    // Attaches one layer of a depth texture array (or one face of a cube-map array's cube:
    // layer = 6 · cube + face) and checks that the framebuffer is complete.
    void attachDepthLayer(const DepthTextureArray& texture, int layer) const;

    void bind() const { counted(glBindFramebuffer, GL_FRAMEBUFFER, id()); }
    void clearColour(int attachment, const float rgba[4]) const;
    // Zero in every channel, for attachments of any format: integer formats take the unsigned
    // integer clear, the others the float clear.
    void clearColourToZero(int attachment) const;
    void clearDepthStencil(float depth, int stencil) const;
    void clearDepth(float depth) const;

private:
    // Each colour attachment's GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, for clearColourToZero.
    std::vector<GLint> componentTypes_;
};

}  // namespace manylights::gl
