// The G-buffer ("seed layout": explicit world position, every quantity displayable) and the
// geometry pass that fills it. docs/gbuffer.md shows each target.
#pragma once

#include <array>
#include <string_view>

#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "gl/Texture.h"

namespace manylights {

class GpuScene;
class PassProfiler;

struct GBufferTarget {
    std::string_view name;
    GLenum format;
    int bytesPerPixel;
    std::string_view contents;
};

// Every quantity in full 32-bit float precision, exactly as the forward shader sees it: the
// deferred image then equals forward's to float rounding, not to the G-buffer's precision
// (tests/image/TechniqueAgreementTest.cpp). Half floats were tried and rejected: llvmpipe
// truncates to half, a relative error of up to 2^-10 in every colour, and the normal's error
// is amplified by specular powers. This explicit layout is for teaching and reference; its
// bytes per pixel are the price (docs/gbuffer.md).
inline constexpr std::array<GBufferTarget, 5> kGBufferColourTargets = {{
    {"position_shininess", GL_RGBA32F, 16, "world-space position xyz, shininess in w"},
    {"normal", GL_RGBA32F, 16, "world-space unit normal xyz, w unused"},
    {"diffuse", GL_RGBA32F, 16, "kd rgb, w unused"},
    {"specular", GL_RGBA32F, 16, "ks rgb, w unused"},
    {"emissive", GL_RGBA32F, 16, "ke rgb (may exceed 1), w unused"},
}};
// Depth and stencil (the stencil serves the stencil-volume technique).
inline constexpr GBufferTarget kDepthStencilTarget = {"depth_stencil", GL_DEPTH24_STENCIL8, 4,
                                                      "24-bit depth, 8-bit stencil"};

constexpr int gbufferBytesPerPixel()
{
    int bytes = kDepthStencilTarget.bytesPerPixel;
    for (const GBufferTarget& target : kGBufferColourTargets)
        bytes += target.bytesPerPixel;
    return bytes;
}

class GBuffer {
public:
    // `depthStencil` is shared with the lit image's framebuffer, so later passes can depth-test
    // against the scene's surfaces.
    GBuffer(int width, int height, const gl::Texture2D& depthStencil);

    // The geometry pass: clears and fills every target, as a profiled pass or not.
    void fill(const GpuScene& scene, PassProfiler& profiler) const;
    void fill(const GpuScene& scene) const;
    // Binds the colour targets to texture units 0..4 (shaders/lib/gbuffer.glsl).
    void bindForReading() const;

private:
    std::array<gl::Texture2D, kGBufferColourTargets.size()> targets_;
    gl::Framebuffer framebuffer_;
    gl::Program program_;
};

}  // namespace manylights
