// The fixed-function state a pass draws with, as one record (render/FramePasses.h). Every
// member's zero is GL's default state (depth test LESS with depth writes, colour writes, no
// blending, culling, depth clamping or stencil test), so a record names only what its pass
// changes, and applying it sets every part: no pass depends on what the one before it left.
#pragma once

#include <cstdint>

namespace manylights {

enum class DepthTest : std::uint8_t {
    Less,
    Off,
    Greater,         // against the scene's depth, for geometry at depth 1: only pixels holding a surface
    GreaterOrEqual,  // a light volume's back faces at or behind the surface
    Equal,           // the same triangles drawn again (GL's invariance rule)
};

enum class Blend : std::uint8_t {
    Replace,
    Add,                // one light batch or volume added to the lit image
    PremultipliedOver,  // transparent surfaces; the lit image's alpha is left as it is
};

enum class Stencil : std::uint8_t {
    Off,
    // A volume's back faces behind the surface add 1, its front faces behind it subtract 1:
    // along a pixel's ray through a convex volume the mark ends non-zero exactly where the
    // surface lies inside.
    CountVolumeFaces,
    // Passes where the mark is set and resets it to 0, so the next light starts clean.
    PassMarkedAndClear,
    // Marks every pixel drawn with 1 (FXAA's edge test), then passes only those.
    MarkDrawn,
    PassMarked,
    // Passes where the mark equals PipelineState::stencilReference and increments it. Passes
    // drawn with references 0, 1, 2, ... over the same pixels each shade a pixel once, however
    // many fragments tie at its depth: forward's lighting draws keep the first drawn of the
    // surfaces that tie at the depth its pre-pass left, the one a single GL_LESS pass keeps.
    OncePerPixel,
};

struct PipelineState {
    DepthTest depthTest = DepthTest::Less;
    bool keepDepth = false;        // no depth writes
    Blend blend = Blend::Replace;  // (blending off)
    bool cullFrontFaces = false;   // draw back faces only (light volumes)
    bool clampDepth = false;       // keep geometry beyond the far plane instead of clipping it
    bool maskColour = false;       // no colour writes
    Stencil stencil = Stencil::Off;
    std::uint8_t stencilReference = 0;  // Stencil::OncePerPixel's
};

// A full-screen triangle at depth 1 over the pixels that hold a surface (shaders/fullscreen.vert).
inline constexpr PipelineState kCoveredPixels{.depthTest = DepthTest::Greater, .keepDepth = true};
// ... adding to the lit image there.
inline constexpr PipelineState kAddToCoveredPixels{
    .depthTest = DepthTest::Greater, .keepDepth = true, .blend = Blend::Add};

// A full-screen triangle over every pixel, whatever the depth (the display pass).
inline constexpr PipelineState kEveryPixel{.depthTest = DepthTest::Off, .keepDepth = true};

// Sets every part of the GL state the record describes.
void applyPipelineState(const PipelineState& state);

}  // namespace manylights
