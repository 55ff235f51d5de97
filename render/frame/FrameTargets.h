// The size-dependent resources of a frame: the depth and the lit image every technique renders
// into, the G-buffer, and the work-counting images. The Renderer rebuilds them on resize; the
// techniques, which hold only size-independent programs, it keeps.
#pragma once

#include "gl/Framebuffer.h"
#include "gl/Texture.h"
#include "render/frame/GBuffer.h"

namespace manylights {

struct FrameTargets {
    FrameTargets(int width, int height, GBufferLayout gbufferLayout = kDefaultGBufferLayout);

    int width;
    int height;
    gl::Texture2D depthStencil;
    gl::Texture2D lit;               // RGBA32F: the unclamped linear colour of docs/lighting.md
    gl::Framebuffer litFramebuffer;  // lit + depthStencil
    GBuffer gbuffer;
    gl::Texture2D lightEvaluations;  // R32UI: pairs evaluated per pixel, when counting work
    gl::Texture2D inRangeCounts;     // R32UI: lights whose A·S > 0 per pixel, when counting
};

}  // namespace manylights
