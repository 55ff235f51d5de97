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

// The most local lights --shadow-lights took before the shadow-page pool (issue 47); the
// command line no longer bounds the option by it, and nothing in the shaders' budget does.
inline constexpr int kMaxShadowLights = 256;

// The iterations of the directional light's shadow lookup, should a compiler not unroll its
// loops: the 3x3 filter of shaders/lib/shadows.glsl runs 3 + 1 outer and 3 · (3 + 1) inner
// iterations, once per pixel. A local light's lookup (shaders/lib/shadow_pages.glsl) is one
// tap and no loop, whatever the number of shadowed lights: it adds nothing to a light walk's
// iterations.
inline constexpr std::uint32_t kShadowLookupIterations = 16;

// The most iterations a pixel spends on shadow lookups: the directional light's, once.
inline constexpr std::uint32_t kShadowLookupBudget = kShadowLookupIterations;

}  // namespace manylights
