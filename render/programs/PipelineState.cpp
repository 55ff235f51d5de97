#include "render/programs/PipelineState.h"

#include <epoxy/gl.h>

#include "gl/CallTally.h"

namespace manylights {

namespace {

void enable(GLenum capability, bool on)
{
    if (on)
        gl::counted(glEnable, capability);
    else
        gl::counted(glDisable, capability);
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
    gl::counted(glCullFace, cullFace(cull));
    // gl_FrontFacing (which two-sided materials light by) follows the winding too.
    gl::counted(glFrontFace, frontFace == Winding::Clockwise ? GL_CW : GL_CCW);
}

void applyPipelineState(const PipelineState& state, int targetWidth, int targetHeight)
{
    // The test stays enabled when off (GL_ALWAYS): a disabled test would also stop depth writes.
    gl::counted(glEnable, GL_DEPTH_TEST);
    gl::counted(glDepthFunc, depthFunction(state.depthTest));
    const GLboolean depthWrites = state.keepDepth ? GL_FALSE : GL_TRUE;
    gl::counted(glDepthMask, depthWrites);

    enable(GL_BLEND, state.blend != Blend::Replace);
    gl::counted(glBlendEquation, GL_FUNC_ADD);
    if (state.blend == Blend::PremultipliedOver)
        gl::counted(glBlendFuncSeparate, GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    else
        gl::counted(glBlendFunc, GL_ONE, GL_ONE);

    applyFaceState(state.cull, state.frontFace);
    enable(GL_POLYGON_OFFSET_FILL, !state.depthBias.isZero());
    gl::counted(glPolygonOffset, state.depthBias.slopeScaled, state.depthBias.constantUnits);
    gl::counted(glPolygonMode, GL_FRONT_AND_BACK, polygonMode(state.polygonMode));
    enable(GL_PROGRAM_POINT_SIZE, state.pointSizeFromShader);
    gl::counted(glPointSize, state.pointSize > 0.0f ? state.pointSize : 1.0f);

    const PixelRect viewport = state.viewport.isZero() ? PixelRect{0, 0, targetWidth, targetHeight} : state.viewport;
    gl::counted(glViewport, viewport.x, viewport.y, viewport.width, viewport.height);
    // With the test off the rectangle has no effect: only the test is switched.
    enable(GL_SCISSOR_TEST, !state.scissor.isZero());
    if (!state.scissor.isZero())
        gl::counted(glScissor, state.scissor.x, state.scissor.y, state.scissor.width, state.scissor.height);
    enable(GL_DEPTH_CLAMP, state.clampDepth);
    const GLboolean colour = state.maskColour ? GL_FALSE : GL_TRUE;
    gl::counted(glColorMask, colour, colour, colour, colour);

    enable(GL_STENCIL_TEST, state.stencil != Stencil::Off);
    switch (state.stencil) {
    case Stencil::Off:
        gl::counted(glStencilFunc, GL_ALWAYS, 0, 0xFF);
        gl::counted(glStencilOp, GL_KEEP, GL_KEEP, GL_KEEP);
        break;
    case Stencil::CountVolumeFaces:
        gl::counted(glStencilFunc, GL_ALWAYS, 0, 0xFF);
        gl::counted(glStencilOpSeparate, GL_BACK, GL_KEEP, GL_INCR_WRAP, GL_KEEP);
        gl::counted(glStencilOpSeparate, GL_FRONT, GL_KEEP, GL_DECR_WRAP, GL_KEEP);
        break;
    case Stencil::PassMarkedAndClear:
        gl::counted(glStencilFunc, GL_NOTEQUAL, 0, 0xFF);
        gl::counted(glStencilOp, GL_KEEP, GL_KEEP, GL_ZERO);
        break;
    case Stencil::MarkDrawn:
        gl::counted(glStencilFunc, GL_ALWAYS, 1, 0xFF);
        gl::counted(glStencilOp, GL_KEEP, GL_KEEP, GL_REPLACE);
        break;
    case Stencil::PassMarked:
        gl::counted(glStencilFunc, GL_EQUAL, 1, 0xFF);
        gl::counted(glStencilOp, GL_KEEP, GL_KEEP, GL_KEEP);
        break;
    case Stencil::OncePerPixel:
        gl::counted(glStencilFunc, GL_EQUAL, state.stencilReference, 0xFF);
        gl::counted(glStencilOp, GL_KEEP, GL_KEEP, GL_INCR_WRAP);
        break;
    }
}

}  // namespace manylights
