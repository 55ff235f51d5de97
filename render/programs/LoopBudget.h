// The loop budget every shader keeps (render/programs/LightBatches.h says why: llvmpipe ends
// every shader loop once one invocation has run 65,535 iterations of all its loops together),
// and the figures of the shadow lookups that every light loop's budget must leave room for.
// Here, in the bottom rooms of render/, so that the culling, the shadows and the programs that
// count against the budget all see the same numbers without including each other.
#pragma once

#include <cstdint>

namespace manylights {

// No invocation of any shader iterates more than this in all its loops together, whatever
// the scene, size or light count: a quarter of llvmpipe's limit, leaving room for the loops
// around a light walk that a comment cannot count exactly.
inline constexpr std::uint32_t kMaxLoopIterations = 16384;

// The most local lights --shadow-lights (and the viewer) may give shadow maps: a cube map of
// 512² faces is 4.5 MiB of depth, so 256 of them already take over a GiB (render/effects/ShadowMaps.h).
inline constexpr int kMaxShadowLights = 256;

// The iterations of one shadow lookup, should a compiler not unroll its loops: the 3x3 filter
// of shaders/lib/shadows.glsl runs 3 + 1 outer and 3 · (3 + 1) inner iterations.
inline constexpr std::uint32_t kShadowLookupIterations = 16;

// The most iterations a pixel spends on shadow lookups: the directional light and every
// shadowed local light, once each.
inline constexpr std::uint32_t kShadowLookupBudget = kShadowLookupIterations * (kMaxShadowLights + 1);

}  // namespace manylights
