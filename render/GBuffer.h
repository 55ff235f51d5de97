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

// Full float precision where the lighting is sensitive to it (position; the normal, which a
// specular power of 64 amplifies), half floats for colours: the deferred image then matches
// forward to within the colours' 11-bit rounding (see tests/image/TechniqueAgreementTest.cpp).
inline constexpr std::array<GBufferTarget, 5> kGBufferColourTargets = {{
    {"position_shininess", GL_RGBA32F, 16, "world-space position xyz, shininess in w"},
    {"normal", GL_RGBA32F, 16, "world-space unit normal xyz, w unused"},
    {"diffuse", GL_RGBA16F, 8, "kd rgb, w unused"},
    {"specular", GL_RGBA16F, 8, "ks rgb, w unused"},
    {"emissive", GL_RGBA16F, 8, "ke rgb (may exceed 1), w unused"},
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

    // The geometry pass: clears and fills every target.
    void fill(const GpuScene& scene, PassProfiler& profiler) const;
    // Binds the colour targets to texture units 0..4 (shaders/lib/gbuffer.glsl).
    void bindForReading() const;

private:
    std::array<gl::Texture2D, kGBufferColourTargets.size()> targets_;
    gl::Framebuffer framebuffer_;
    gl::Program program_;
};

}  // namespace manylights
