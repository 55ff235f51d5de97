#include "gl/Framebuffer.h"

#include "core/Error.h"

namespace manylights::gl {

Framebuffer::Framebuffer(std::string_view label, std::span<const Texture2D* const> colour, const Texture2D* depth)
    : GlObject(detail::createName(glCreateFramebuffers))
{
    setLabel(GL_FRAMEBUFFER, id(), label);
    std::vector<GLenum> drawBuffers;
    GLenum attachment = GL_COLOR_ATTACHMENT0;
    for (const Texture2D* texture : colour) {
        glNamedFramebufferTexture(id(), attachment, texture->id(), 0);
        GLint componentType = GL_NONE;
        glGetNamedFramebufferAttachmentParameteriv(id(), attachment, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE,
                                                   &componentType);
        componentTypes_.push_back(componentType);
        drawBuffers.push_back(attachment++);
    }
    glNamedFramebufferDrawBuffers(id(), static_cast<GLsizei>(drawBuffers.size()), drawBuffers.data());
    if (depth) {
        const bool hasStencil = depth->format() == GL_DEPTH24_STENCIL8 || depth->format() == GL_DEPTH32F_STENCIL8;
        glNamedFramebufferTexture(id(), hasStencil ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT, depth->id(), 0);
    }
    ML_ASSERT(glCheckNamedFramebufferStatus(id(), GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE);
}

Framebuffer::Framebuffer(std::string_view label) : GlObject(detail::createName(glCreateFramebuffers))
{
    setLabel(GL_FRAMEBUFFER, id(), label);
    glNamedFramebufferDrawBuffer(id(), GL_NONE);
}

void Framebuffer::attachDepthLayer(const DepthTextureArray& texture, int layer) const
{
    glNamedFramebufferTextureLayer(id(), GL_DEPTH_ATTACHMENT, texture.id(), 0, layer);
    ML_ASSERT(glCheckNamedFramebufferStatus(id(), GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE);
}

void Framebuffer::clearDepth(float depth) const { glClearNamedFramebufferfv(id(), GL_DEPTH, 0, &depth); }

void Framebuffer::clearColour(int attachment, const float rgba[4]) const
{
    glClearNamedFramebufferfv(id(), GL_COLOR, attachment, rgba);
}

void Framebuffer::clearColourToZero(int attachment) const
{
    // Clearing an integer attachment with the float clear is undefined (GL 4.5, 17.4.3.1).
    switch (componentTypes_.at(static_cast<std::size_t>(attachment))) {
    case GL_UNSIGNED_INT: {
        const GLuint zero[4] = {0, 0, 0, 0};
        glClearNamedFramebufferuiv(id(), GL_COLOR, attachment, zero);
        break;
    }
    case GL_INT: {
        const GLint zero[4] = {0, 0, 0, 0};
        glClearNamedFramebufferiv(id(), GL_COLOR, attachment, zero);
        break;
    }
    default: {
        const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
        clearColour(attachment, zero);
    }
    }
}

void Framebuffer::clearDepthStencil(float depth, int stencil) const
{
    glClearNamedFramebufferfi(id(), GL_DEPTH_STENCIL, 0, depth, stencil);
}

}  // namespace manylights::gl
