// The fixed-function state a pass draws with, as one record (render/frame/FramePasses.h). Every
// member's zero is GL's default state (depth test LESS with depth writes, colour writes, no
// blending, culling, depth bias, depth clamping, scissor or stencil test, counter-clockwise
// front faces, filled polygons, 1-pixel points) and the viewport of the whole target, so a
// record names only what its pass changes, and applying it sets every part: no pass depends
// on what the one before it left.
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

enum class Cull : std::uint8_t {
    None,
    BackFaces,   // one-sided surfaces
    FrontFaces,  // draw back faces only (light volumes, a two-sided transparent surface's far layer)
};

// How polygons are drawn (glPolygonMode): filled, as their edges, or as their corners.
enum class PolygonMode : std::uint8_t { Fill, Lines, Points };

// Which winding faces the viewer (glFrontFace): a mirroring transform turns its mesh's over.
enum class Winding : std::uint8_t { CounterClockwise, Clockwise };

// Depth bias (glPolygonOffset): a slope-scaled factor and a constant in units of the depth
// buffer's resolution. Zero: none.
struct DepthBias {
    float slopeScaled = 0.0f;
    float constantUnits = 0.0f;
    constexpr bool isZero() const { return slopeScaled == 0.0f && constantUnits == 0.0f; }
};

// A rectangle of pixels from the target's lower left corner. Zero: the record's default (the
// whole target for a viewport, no scissor test for a scissor).
struct PixelRect {
    int x = 0;
    int y = 0;
    int width = 0;
    int height = 0;
    constexpr bool isZero() const { return x == 0 && y == 0 && width == 0 && height == 0; }
    friend constexpr bool operator==(const PixelRect&, const PixelRect&) = default;
};

struct PipelineState {
    DepthTest depthTest = DepthTest::Less;
    bool keepDepth = false;        // no depth writes
    Blend blend = Blend::Replace;  // (blending off)
    Cull cull = Cull::None;
    bool clampDepth = false;  // keep geometry beyond the far plane instead of clipping it
    bool maskColour = false;  // no colour writes
    Stencil stencil = Stencil::Off;
    std::uint8_t stencilReference = 0;  // Stencil::OncePerPixel's
    Winding frontFace = Winding::CounterClockwise;
    DepthBias depthBias{};
    PixelRect viewport{};  // zero: the whole target
    PixelRect scissor{};   // zero: no scissor test
    // Points as large as the vertex shader's gl_PointSize (GL_PROGRAM_POINT_SIZE), else of
    // `pointSize` pixels (zero: 1, GL's default).
    bool pointSizeFromShader = false;
    float pointSize = 0.0f;
    PolygonMode polygonMode = PolygonMode::Fill;
};

// A full-screen triangle at depth 1 over the pixels that hold a surface (shaders/fullscreen.vert).
inline constexpr PipelineState kCoveredPixels{.depthTest = DepthTest::Greater, .keepDepth = true};
// ... adding to the lit image there.
inline constexpr PipelineState kAddToCoveredPixels{
    .depthTest = DepthTest::Greater, .keepDepth = true, .blend = Blend::Add};

// ... over the pixels that hold none, whose depth is the clear's 1 (the environment's background).
inline constexpr PipelineState kUncoveredPixels{.depthTest = DepthTest::Equal, .keepDepth = true};

// A full-screen triangle over every pixel, whatever the depth (the display pass).
inline constexpr PipelineState kEveryPixel{.depthTest = DepthTest::Off, .keepDepth = true};

// Sets every part of the GL state the record describes, for a target of `targetWidth` x
// `targetHeight` pixels (the viewport's zero).
void applyPipelineState(const PipelineState& state, int targetWidth, int targetHeight);

// The faces part alone: for a draw list whose items differ in culling and winding within one
// pass (render/scene/DrawList.h). The pass's record restores both when the pass ends.
void applyFaceState(Cull cull, Winding frontFace);

}  // namespace manylights
