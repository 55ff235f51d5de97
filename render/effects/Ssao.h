// Screen-space ambient occlusion (docs/shadows.md): hemisphere sampling in view space over the
// G-buffer of the visible surfaces, then a 4x4 blur. The Renderer runs it before the
// technique; shaders/lib/shadows.glsl multiplies the ambient term by the result (unit 13), so
// every technique, forward included, reads the same occlusion for the same pixel.
#pragma once

#include <array>

#include <glm/glm.hpp>

#include "gl/Buffer.h"
#include "gl/Program.h"
#include "gl/Texture.h"
#include "render/frame/GBuffer.h"
#include "render/programs/Bindings.h"
#include "scene/Scene.h"

namespace manylights {

class GpuScene;
class FramePasses;
struct FrameTargets;

inline constexpr GLuint kAmbientOcclusionUnit =
    bindings::AMBIENT_OCCLUSION_UNIT;                                      // the blurred factor (lib/shadows.glsl)
inline constexpr GLuint kRawOcclusionUnit = bindings::RAW_OCCLUSION_UNIT;  // the unblurred factor, read by the blur
inline constexpr int kSsaoKernelSize = 16;                                 // KERNEL_SIZE of shaders/ssao.comp

// The std430 layout of SsaoSamples in shaders/ssao.comp.
struct SsaoSamples {
    std::array<glm::vec4, kSsaoKernelSize> kernel;  // xyz in the unit hemisphere around +z
    std::array<glm::vec4, 16> noise;                // xy: unit vectors of the 4x4 noise tile
};

// The kernel and noise, the same on every run and every platform (a fixed-seed generator of
// our own, not <random>'s distributions, whose results differ between standard libraries).
// Every kernel point lies at least 10° above the tangent plane and within the unit
// hemisphere, denser near the centre (scale 0.1 to 1 growing quadratically with the index).
SsaoSamples makeSsaoSamples();

class Ssao {
public:
    // `layout`: the G-buffer layout the occlusion pass reads surfaces from.
    explicit Ssao(GBufferLayout layout);

    // Computes the occlusion of the visible surfaces for `settings`: fills the G-buffer (the
    // forward technique has none of its own) and runs the occlusion and blur passes. Leaves
    // the blurred result bound to unit 13.
    void run(const AmbientOcclusion& settings, FramePasses& passes);

private:
    void resize(int width, int height);

    gl::Program occlusionProgram_;
    gl::Program blurProgram_;
    gl::Buffer samples_;
    gl::Texture2D raw_;
    gl::Texture2D blurred_;
};

}  // namespace manylights
