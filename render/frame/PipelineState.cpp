#include "render/frame/PipelineState.h"

#include <epoxy/gl.h>

namespace manylights {

namespace {

void enable(GLenum capability, bool on)
{
    if (on)
        glEnable(capability);
    else
        glDisable(capability);
}

GLenum depthFunction(DepthTest test)
{
    switch (test) {
    case DepthTest::Less: return GL_LESS;
    case DepthTest::Off: return GL_ALWAYS;
    case DepthTest::Greater: return GL_GREATER;
    case DepthTest::GreaterOrEqual: return GL_GEQUAL;
    case DepthTest::Equal: return GL_EQUAL;
    }
    return GL_LESS;
}

GLenum polygonMode(PolygonMode mode)
{
    switch (mode) {
    case PolygonMode::Fill: return GL_FILL;
    case PolygonMode::Lines: return GL_LINE;
    case PolygonMode::Points: return GL_POINT;
    }
    return GL_FILL;
}

GLenum cullFace(Cull cull) { return cull == Cull::FrontFaces ? GL_FRONT : GL_BACK; }

}  // namespace

void applyFaceState(Cull cull, Winding frontFace)
{
    enable(GL_CULL_FACE, cull != Cull::None);
    glCullFace(cullFace(cull));
    // gl_FrontFacing (which two-sided materials light by) follows the winding too.
    glFrontFace(frontFace == Winding::Clockwise ? GL_CW : GL_CCW);
}

void applyPipelineState(const PipelineState& state, int targetWidth, int targetHeight)
{
    // The test stays enabled when off (GL_ALWAYS): a disabled test would also stop depth writes.
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(depthFunction(state.depthTest));
    glDepthMask(state.keepDepth ? GL_FALSE : GL_TRUE);

    enable(GL_BLEND, state.blend != Blend::Replace);
    glBlendEquation(GL_FUNC_ADD);
    if (state.blend == Blend::PremultipliedOver)
        glBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    else
        glBlendFunc(GL_ONE, GL_ONE);

    applyFaceState(state.cull, state.frontFace);
    enable(GL_POLYGON_OFFSET_FILL, !state.depthBias.isZero());
    glPolygonOffset(state.depthBias.slopeScaled, state.depthBias.constantUnits);
    glPolygonMode(GL_FRONT_AND_BACK, polygonMode(state.polygonMode));
    enable(GL_PROGRAM_POINT_SIZE, state.pointSizeFromShader);
    glPointSize(state.pointSize > 0.0f ? state.pointSize : 1.0f);

    const PixelRect viewport = state.viewport.isZero() ? PixelRect{0, 0, targetWidth, targetHeight} : state.viewport;
    glViewport(viewport.x, viewport.y, viewport.width, viewport.height);
    // With the test off the rectangle has no effect: only the test is switched.
    enable(GL_SCISSOR_TEST, !state.scissor.isZero());
    if (!state.scissor.isZero())
        glScissor(state.scissor.x, state.scissor.y, state.scissor.width, state.scissor.height);
    enable(GL_DEPTH_CLAMP, state.clampDepth);
    const GLboolean colour = state.maskColour ? GL_FALSE : GL_TRUE;
    glColorMask(colour, colour, colour, colour);

    enable(GL_STENCIL_TEST, state.stencil != Stencil::Off);
    switch (state.stencil) {
    case Stencil::Off:
        glStencilFunc(GL_ALWAYS, 0, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        break;
    case Stencil::CountVolumeFaces:
        glStencilFunc(GL_ALWAYS, 0, 0xFF);
        glStencilOpSeparate(GL_BACK, GL_KEEP, GL_INCR_WRAP, GL_KEEP);
        glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_DECR_WRAP, GL_KEEP);
        break;
    case Stencil::PassMarkedAndClear:
        glStencilFunc(GL_NOTEQUAL, 0, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_ZERO);
        break;
    case Stencil::MarkDrawn:
        glStencilFunc(GL_ALWAYS, 1, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
        break;
    case Stencil::PassMarked:
        glStencilFunc(GL_EQUAL, 1, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        break;
    case Stencil::OncePerPixel:
        glStencilFunc(GL_EQUAL, state.stencilReference, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_INCR_WRAP);
        break;
    }
}

}  // namespace manylights
