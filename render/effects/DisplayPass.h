// The display pass: the lit image of any technique to the picture a screen or an 8-bit file
// shows (docs/display.md). One full-screen pass box-filters supersampled frames down in linear
// light and applies exposure, the tone curve and the sRGB encoding (shaders/display.frag);
// an optional second one anti-aliases the result (shaders/fxaa.frag). Both run after
// lighting, so every technique stays equal to forward before them.
#pragma once

#include <compare>

#include "gl/Buffer.h"
#include "gl/Framebuffer.h"
#include "gl/Program.h"
#include "gl/Texture.h"
#include "gl/VertexArray.h"
#include "render/frame/FramePasses.h"
#include "render/programs/ProgramVariants.h"
#include "scene/DisplaySettings.h"

namespace manylights {

// What display.frag's program is compiled for: the tone curve (TONE_CURVE), the sRGB encoding
// (SRGB_ENCODE), the supersampling it filters down (SUPERSAMPLE), and whether it also writes
// its picture to the second target, FXAA's output (COPY_OUTPUT).
struct DisplayVariant {
    ToneCurve curve{};
    bool srgb = false;
    int supersample = 1;
    bool copy = false;

    auto operator<=>(const DisplayVariant&) const = default;

    gl::Defines toDefines(gl::Defines defines) const;
};

class DisplayPass {
public:
    // Passes of the frame from its lit image, whose size divided by `supersample` (which must
    // divide it) is the output's size.
    void run(FramePasses& passes, const DisplaySettings& settings, int supersample);

    // The last run's picture: RGBA8, display-encoded (alpha: luma, for FXAA); its framebuffer
    // is for blitting to a window. 8 bits: what every consumer of it shows.
    const gl::Texture2D& output() const { return antialiased_ ? antialiasedOutput_ : transformed_; }
    const gl::Framebuffer& outputFramebuffer() const
    {
        return antialiased_ ? antialiasedFramebuffer_ : transformedFramebuffer_;
    }

    // The log-average luminance of `lit` where `depth` holds a surface (shaders/
    // log_luminance.comp, on a grid of points), for auto-exposure: an exposure of
    // log2(0.18 / it) maps the average to middle grey. Waits for the GPU to read it back.
    float logAverageLuminance(const gl::Texture2D& lit, const gl::Texture2D& depth);

private:
    void resize(int width, int height);

    ProgramVariants<DisplayVariant> transformPrograms_{
        "display transform", {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "display.frag"}}};
    gl::Program fxaaEdgesProgram_;  // made on first use, with fxaaProgram_
    gl::Program fxaaProgram_;
    gl::VertexArray emptyVertexArray_{"display pass"};  // the full-screen triangle needs no attributes
    gl::Texture2D transformed_;
    gl::Framebuffer transformedFramebuffer_;
    // transformed_ and antialiasedOutput_ together: with FXAA the display pass writes its
    // picture to both, so that FXAA rewrites only the edge pixels of a copy made for free
    // (a glCopyImageSubData of the whole picture cost a pass of its own).
    gl::Framebuffer transformedAndCopyFramebuffer_;
    gl::Texture2D antialiasedOutput_;
    gl::Texture2D edgeStencil_;  // FXAA's edge pixels (shaders/fxaa_edges.frag)
    gl::Framebuffer antialiasedFramebuffer_;
    bool antialiased_ = false;
    gl::Program luminanceProgram_;  // made on first use
    gl::Buffer luminance_;
};

}  // namespace manylights
