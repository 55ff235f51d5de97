#include "render/effects/DisplayPass.h"
#include "render/programs/Bindings.h"

#include <cmath>
#include <string>

#include "core/Error.h"
#include "render/programs/Locations.h"
#include "render/programs/PipelineState.h"

namespace manylights {

gl::Defines DisplayVariant::toDefines(gl::Defines defines) const
{
    defines.emplace_back("TONE_CURVE", std::to_string(static_cast<int>(curve)));
    defines.emplace_back("SUPERSAMPLE", std::to_string(supersample));
    if (srgb)
        defines.emplace_back("SRGB_ENCODE", "1");
    if (copy)
        defines.emplace_back("COPY_OUTPUT", "1");
    return defines;
}

void DisplayPass::resize(int width, int height)
{
    if (transformed_.width() == width && transformed_.height() == height)
        return;
    antialiasedFramebuffer_ = gl::Framebuffer();
    transformedAndCopyFramebuffer_ = gl::Framebuffer();
    antialiasedOutput_ = gl::Texture2D();
    edgeStencil_ = gl::Texture2D();
    transformedFramebuffer_ = gl::Framebuffer();
    transformed_ = gl::Texture2D("display", GL_RGBA8, width, height);
    // FXAA samples it between texels.
    transformed_.setLinearFiltering();
    transformed_.setWrap(GL_CLAMP_TO_EDGE);
    transformedFramebuffer_ = gl::Framebuffer("display", {&transformed_}, nullptr);
    antialiasedOutput_ = gl::Texture2D("display anti-aliased", GL_RGBA8, width, height);
    edgeStencil_ = gl::Texture2D("display edges", GL_DEPTH24_STENCIL8, width, height);
    antialiasedFramebuffer_ = gl::Framebuffer("display anti-aliased", {&antialiasedOutput_}, &edgeStencil_);
    transformedAndCopyFramebuffer_ =
        gl::Framebuffer("display and its copy", {&transformed_, &antialiasedOutput_}, nullptr);
}

void DisplayPass::run(FramePasses& passes, const DisplaySettings& settings, int supersample)
{
    const gl::Texture2D& lit = passes.targets().lit;
    ML_ASSERT(supersample >= 1 && supersample <= kMaxSupersample);
    ML_ASSERT(lit.width() % supersample == 0 && lit.height() % supersample == 0);
    const int width = lit.width() / supersample;
    const int height = lit.height() / supersample;
    resize(width, height);
    antialiased_ = settings.antialiasing == Antialiasing::Fxaa;
    const PixelRect output{0, 0, width, height};
    PipelineState everyPixel = kEveryPixel;
    everyPixel.viewport = output;
    passes.run(
        {.name = "display",
         .framebuffer = antialiased_ ? &transformedAndCopyFramebuffer_ : &transformedFramebuffer_,
         .state = everyPixel,
         .sampled = Resource::LitImage},
        [&] {
            const gl::Program& program = transformPrograms_.variant(
                {.curve = settings.toneCurve, .srgb = settings.srgb, .supersample = supersample, .copy = antialiased_});
            program.set(locations::DISPLAY_EXPOSURE_SCALE_LOCATION, std::exp2(settings.exposure));
            lit.bindUnit(bindings::DISPLAY_SOURCE_UNIT);
            emptyVertexArray_.bind();
            program.use();
            glDrawArrays(GL_TRIANGLES, 0, 3);  // every pixel: shaders/fullscreen.vert's triangle
        });
    if (!antialiased_)
        return;
    if (!fxaaProgram_) {
        fxaaEdgesProgram_ =
            gl::Program("fxaa edges", {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "fxaa_edges.frag"}});
        fxaaProgram_ = gl::Program("fxaa", {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "fxaa.frag"}});
    }
    // Most pixels are not on an edge and keep their colour, which the display pass wrote to
    // the output as well; the edge test marks the others in the stencil buffer and the filter
    // runs on those only (llvmpipe skips stencil-failed pixels before shading, not pixels that
    // return early).
    const auto fxaaPass = [&](Stencil stencil, bool maskColour, const gl::Program& program) {
        passes.run({.name = "fxaa",
                    .framebuffer = &antialiasedFramebuffer_,
                    .state = {.depthTest = DepthTest::Off,
                              .keepDepth = true,
                              .maskColour = maskColour,
                              .stencil = stencil,
                              .viewport = output}},
                   [&] {
                       if (stencil == Stencil::MarkDrawn)
                           antialiasedFramebuffer_.clearDepthStencil(1.0f, 0);
                       transformed_.bindUnit(bindings::DISPLAY_SOURCE_UNIT);
                       emptyVertexArray_.bind();
                       program.use();
                       glDrawArrays(GL_TRIANGLES, 0, 3);
                   });
    };
    fxaaPass(Stencil::MarkDrawn, true, fxaaEdgesProgram_);
    fxaaPass(Stencil::PassMarked, false, fxaaProgram_);
}

float DisplayPass::logAverageLuminance(const gl::Texture2D& lit, const gl::Texture2D& depth)
{
    if (!luminanceProgram_) {
        luminanceProgram_ = gl::Program("log-average luminance", {{GL_COMPUTE_SHADER, "log_luminance.comp"}});
        luminance_ = gl::Buffer("log-average luminance", sizeof(float), nullptr);
    }
    lit.bindUnit(bindings::DISPLAY_SOURCE_UNIT);
    depth.bindUnit(bindings::LUMINANCE_DEPTH_UNIT);
    luminance_.bindBase(GL_SHADER_STORAGE_BUFFER, bindings::LUMINANCE_RESULT_BUFFER_BINDING);
    luminanceProgram_.use();
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    float value = 0.0f;
    luminance_.read(0, sizeof(value), &value);
    return value;
}

}  // namespace manylights
