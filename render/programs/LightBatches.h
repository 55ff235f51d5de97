// Light batches: why no shader loops over more than kLightsPerBatch lights.
//
// Mesa's llvmpipe ends every shader loop without a word once one invocation has run 65,535
// iterations of all its loops together (gallivm's loop limiter, LP_MAX_TGSI_LOOP_ITERATIONS:
// one counter per invocation, decremented at the end of every iteration of every loop);
// tests/gl/GlTest.cpp (LoopLimit) shows it. A pixel that looped over 131,072 lights in one
// invocation silently got the first 65,535 of them. So every pass whose per-pixel loop runs
// over lights takes at most kLightsPerBatch of them, with the batch's bounds in a uniform
// (shaders/lib/light_batch.glsl); a frame with more lights runs the pass once per batch,
// adding to the lit image. The first batch also adds the light-independent terms.
//
// The rule for every shader in this project: no invocation iterates more than
// kMaxLoopIterations (render/programs/LoopBudget.h) times in all, whatever the scene, size or light count. A batch's
// loops stay under it with room for the iterations around them: word walks of bit masks and per-tile culling, which
// each shader's comment counts, and the directional light's 3x3 shadow filter of shaders/lib/shadows.glsl
// (kShadowLookupBudget; a local light's shadow is one tap with no loop; LightBatches.cpp checks the sum).
#pragma once

#include <cstdint>
#include <vector>

#include "gl/Program.h"
#include "render/programs/Bindings.h"
#include "render/programs/LoopBudget.h"

namespace manylights {

inline constexpr std::uint32_t kLightsPerBatch = 8192;  // LightBatches.cpp checks it against the bound

// Lights [first, end) of the scene's light buffer.
struct LightBatch {
    std::uint32_t first = 0;
    std::uint32_t end = 0;

    bool isFirst() const { return first == 0; }
    std::uint32_t size() const { return end - first; }
};

// The batches that cover `lightCount` lights, `perBatch` at most each, in order. Always at
// least one, so that a scene without local lights still gets its light-independent terms.
std::vector<LightBatch> lightBatches(std::uint32_t lightCount, std::uint32_t perBatch = kLightsPerBatch);

// Makes `batch` the one `program` loops over (at shaders/lib/locations.glsl's
// LIGHT_BATCH_LOCATION).
void setLightBatch(const gl::Program& program, const LightBatch& batch);

// Light windows: a batch's lights as a uniform block (shaders/lib/lights.glsl, built with
// LIGHT_WINDOW_BINDING) instead of the storage buffer, for passes where every pixel walks the
// same lights in order (deferred) and for frames of one small batch (clustered). llvmpipe
// reads a uniform block with one vector gather per value and a storage buffer lane by lane,
// testing each lane's bounds (a quarter of the deferred lighting pass on LearnOpenGL's scene,
// docs/performance.md); a GPU broadcasts a uniform read that every thread shares. A window is
// 64 KiB of lights, the uniform block size of desktop drivers (GL guarantees only 16 KiB:
// lightWindowsSupported says), so such passes take batches of kLightsPerWindow.
inline constexpr std::size_t kLightWindowBytes = 64 * 1024;
inline constexpr std::uint32_t kLightsPerWindow = 1024;  // SceneLights.cpp checks it fills the window
// The window's uniform buffer binding (0 and 1 are lib/frame.glsl's and lib/shadows.glsl's).
inline constexpr unsigned kLightWindowBinding = bindings::LIGHT_WINDOW_BLOCK_BINDING;
// Whether a frame lit in `batches` can read its lights from one window: a single batch of at
// most kLightsPerWindow. (Windows start at multiples of kLightsPerWindow; batches sized for
// another budget, such as clustered's masks at 8192x4096, need not.)
bool fitsOneLightWindow(const std::vector<LightBatch>& batches);
// Whether GL_MAX_UNIFORM_BLOCK_SIZE holds a window.
bool lightWindowsSupported();

// Light texels: the whole light buffer read through a texture buffer, four RGBA32F texels per
// light (shaders/lib/lights.glsl, built with LIGHT_TEXELS), for passes whose pixels read
// different lights by index (tiled-quads, tiled, clustered, the transparency pass), and on a
// software rasteriser for every pass (GpuScene::readsLightWindows): a window holds 1,024
// lights, and llvmpipe loads from a storage buffer lane by lane, testing each lane's bounds,
// and gathers from a uniform block per component, where it fetches a texel for 8 lanes at
// once. On the courtyard at 4096
// lights, 1280x720, the lighting passes took 267 -> 141 ms (tiled-quads), 298-304 ->
// 246-262 ms (tiled) and 113-116 -> 98-100 ms (clustered) with them (docs/performance.md).
inline constexpr unsigned kLightTexelsUnit = bindings::LIGHT_TEXELS_UNIT;
inline constexpr std::size_t kTexelsPerLight = 4;
// Whether the driver has a 17th texture unit in fragment and compute shaders and a texture
// buffer of 4 × `lightCount` texels (GL promises 16 units and 65,536 texels; desktop drivers
// have 32 and 2^27). Where it has not, those passes read the storage buffer.
bool lightTexelsSupported(std::size_t lightCount);

}  // namespace manylights
