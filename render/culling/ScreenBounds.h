// The pixels a ball can cover on screen, from its tangent planes through the eye: which tiles
// tiled-quads' CPU culling tests a light against (render/culling/TileCulling.h), and which
// screen cells a light volume occupies in the stencil technique's batches
// (render/volumes/StencilBatches.h).
#pragma once

#include <utility>

namespace manylights {

// The projected rectangle only decides which tiles or cells a ball may touch: padded by two
// pixels for the rounding of this code, of the GPU's vertex transform and of its rasteriser's
// snapping to sub-pixel positions (a fraction of a pixel).
inline constexpr double kRectanglePaddingPixels = 2.0;

// The pixels, along one image axis, that a ball in front of the eye (depth > radius) projects
// onto: the slopes lateral / depth of its two tangent planes through the eye that contain the
// other image axis, mapped to window coordinates (0 to `pixels`) for a view whose half field of
// view along the axis has tangent `tanHalf`. Exact for the ball, then padded; the bounds may lie
// beyond the image, and are not numbers when depth ≤ radius.
std::pair<double, double> projectedPixels(double lateral, double depth, double radius, double tanHalf, int pixels);

// The tiles [first, last] of `tileSize` pixels, of `tiles` along the axis, that the window
// interval [low, high] touches: empty (first > last) when it lies beyond the image, all of them
// when a bound is not a number.
std::pair<int, int> tileSpan(double low, double high, int tileSize, int tiles);

}  // namespace manylights
