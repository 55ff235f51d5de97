// The G-buffer in one of two layouts (seed: explicit world position, every quantity a 32-bit
// float; compact: position from depth, packed normal and colours) and the geometry pass that
// fills it. docs/gbuffer.md shows each target.
#pragma once

#include <array>
#include <span>
#include <string_view>
#include <vector>

#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "gl/Texture.h"
#include "render/programs/Bindings.h"
#include "render/programs/GBufferLayout.h"
#include "render/programs/LightingPrograms.h"

namespace manylights {

class GpuScene;
class FramePasses;

struct GBufferTarget {
    std::string_view name;
    GLenum format;
    int bytesPerPixel;
    int unit;  // the texture unit the lighting passes read it from (shaders/lib/bindings.glsl)
    std::string_view contents;
};

// Seed layout: every quantity in full 32-bit float precision, exactly as the forward shader
// sees it: the deferred image then equals forward's to float rounding, not to the G-buffer's
// precision (tests/image/TechniqueAgreementTest.cpp). Half floats were tried and rejected:
// llvmpipe truncates to half, a relative error of up to 2^-10 in every colour, and the normal's
// error is amplified by specular powers. This explicit layout is for teaching and reference;
// its bytes per pixel are the price (docs/gbuffer.md).
inline constexpr std::array<GBufferTarget, 5> kSeedGBufferTargets = {{
    {"position_shininess", GL_RGBA32F, 16, bindings::GBUFFER_POSITION_UNIT, "world-space position xyz, shininess in w"},
    {"normal", GL_RGBA32F, 16, bindings::GBUFFER_NORMAL_UNIT, "world-space unit normal xyz, w unused"},
    {"diffuse", GL_RGBA32F, 16, bindings::GBUFFER_DIFFUSE_UNIT, "kd rgb, w unused"},
    {"specular", GL_RGBA32F, 16, bindings::GBUFFER_SPECULAR_UNIT, "ks rgb, w unused"},
    {"emissive", GL_RGBA32F, 16, bindings::GBUFFER_EMISSIVE_UNIT, "ke rgb (may exceed 1), w unused"},
}};

// Compact layout (the default; docs/gbuffer.md derives each precision and the test tolerances):
// - The position is not stored: a 32-bit float view depth (distance along the view axis) and
//   the pixel's ray give it back. The hardware depth (24-bit, non-linear) would lose ~1e-4 of
//   a unit at 15 units from a 0.1 near plane, far more than float rounding, and a 32-bit float
//   depth buffer has the same 2^-24 steps near 1; a linear float depth keeps ~1e-7 relative.
// - The normal is octahedral-encoded in two 16-bit unorms: ≤ ~3e-5 rad of error.
// - kd and ks in 8-bit unorm (≤ 0.5/255 absolute per channel); the shininess as a 16-bit code
//   of log2(s) / 16, a byte on top of each (s in [1, 65536], ≤ 8.5e-5 relative).
// - ke may exceed 1 (light markers), so it stays floating point: half floats, ≤ 2^-10
//   relative (llvmpipe truncates). R11G11B10F would save 4 bytes at 2^-5 relative in blue.
// All but ke are packed into one RGBA32UI texel (packSurface() in shaders/lib/gbuffer_packing.glsl)
// rather than four targets of their own, with the same bits: every read of a surface is one
// texel fetch instead of four, and llvmpipe's fetch costs per fetch, not per byte (the light
// volumes read the surface once per (pixel, light) pair; docs/performance.md).
inline constexpr std::array<GBufferTarget, 2> kCompactGBufferTargets = {{
    {"surface", GL_RGBA32UI, 16, bindings::GBUFFER_SURFACE_UNIT,
     "x: view-space depth along the view axis (float bits; position = eye + ray · depth); y: octahedral-encoded "
     "world-space unit normal (2 x 16-bit unorm); z: kd rgb and the high byte of the 16-bit log2 shininess code "
     "(4 x 8-bit unorm); w: ks rgb and the code's low byte"},
    {"emissive", GL_RGBA16F, 8, bindings::GBUFFER_EMISSIVE_UNIT, "ke rgb as half floats (may exceed 1); a unused"},
}};

constexpr std::span<const GBufferTarget> gbufferColourTargets(GBufferLayout layout)
{
    if (layout == GBufferLayout::Seed)
        return kSeedGBufferTargets;
    return kCompactGBufferTargets;
}

// Depth and stencil (the stencil serves the stencil-volume technique); both layouts share it.
inline constexpr GBufferTarget kDepthStencilTarget = {"depth_stencil", GL_DEPTH24_STENCIL8, 4, -1,
                                                      "24-bit depth, 8-bit stencil"};

constexpr int gbufferBytesPerPixel(GBufferLayout layout)
{
    int bytes = kDepthStencilTarget.bytesPerPixel;
    for (const GBufferTarget& target : gbufferColourTargets(layout))
        bytes += target.bytesPerPixel;
    return bytes;
}
static_assert(2 * gbufferBytesPerPixel(GBufferLayout::Compact) <= gbufferBytesPerPixel(GBufferLayout::Seed),
              "the compact layout must take at most half the seed layout's memory");

class GBuffer {
public:
    // `depthStencil` is shared with the lit image's framebuffer, so later passes can depth-test
    // against the scene's surfaces.
    GBuffer(int width, int height, const gl::Texture2D& depthStencil, GBufferLayout layout);

    GBufferLayout layout() const { return layout_; }

    // The frame's geometry pass: clears and fills every target, unless they already hold this
    // frame's surfaces (SSAO fills them before the technique does; drawing the scene twice
    // would change nothing but the cost).
    void fill(FramePasses& passes);
    // Clears and fills every target, always, outside the frame's passes.
    void fill(const GpuScene& scene) const;
    // The targets no longer hold the current frame: the Renderer calls it as a frame begins.
    void invalidate() { current_ = false; }
    // Binds each colour target to its texture unit (shaders/lib/gbuffer.glsl).
    void bindForReading() const;
    const gl::Framebuffer& framebuffer() const { return framebuffer_; }

private:
    void clearAndDraw(const GpuScene& scene) const;

    GBufferLayout layout_;
    std::vector<gl::Texture2D> targets_;  // the layout's colour targets, in attachment order
    gl::Framebuffer framebuffer_;
    LightingProgram programs_;  // one per set of material maps
    bool current_ = false;      // filled since the last invalidate()
};

}  // namespace manylights
