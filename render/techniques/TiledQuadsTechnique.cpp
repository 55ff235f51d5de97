#include "render/techniques/TiledQuadsTechnique.h"
#include "render/programs/Bindings.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <string>

#include "render/frame/FramePasses.h"
#include "render/frame/ScreenPasses.h"
#include "render/programs/Locations.h"
#include "render/scene/GpuScene.h"

namespace manylights {

namespace {

// Locations and bindings of shaders/tiled_quads.vert and tiled_quads.frag (binding 0 is
// the light buffer).
constexpr GLint kFirstQuad = locations::TILE_FIRST_QUAD_LOCATION;
constexpr GLint kTilesX = locations::TILES_X_LOCATION;
constexpr GLint kTileSize = locations::TILE_SIZE_LOCATION;
constexpr GLint kViewportSize = locations::TILE_VIEWPORT_SIZE_LOCATION;
constexpr GLint kTilesAsPoints = locations::TILES_AS_POINTS_LOCATION;
constexpr GLuint kTileQuadsBinding = bindings::TILE_QUADS_BUFFER_BINDING;
constexpr GLuint kTileLightsBinding = bindings::TILE_LIGHTS_BUFFER_BINDING;

// The variant that draws a quad with 0 < `count` ≤ kLightsPerBatch lights.
std::size_t variantFor(std::uint32_t count)
{
    const auto bound = std::lower_bound(kTileLightBounds.begin(), kTileLightBounds.end(), count);
    return static_cast<std::size_t>(bound - kTileLightBounds.begin());
}

}  // namespace

TiledQuadsTechnique::TiledQuadsTechnique(const TechniqueOptions& options)
    : Technique(options),
      global_("global terms", {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "global.frag"}},
              options.shaders),
      quads_("tiled quads", {{GL_VERTEX_SHADER, "tiled_quads.vert"}, {GL_FRAGMENT_SHADER, "tiled_quads.frag"}},
             options.shaders),
      culler_(options.culling.cullingThreads.value_or(0))
{
    GLfloat pointSizes[2] = {};
    glGetFloatv(GL_POINT_SIZE_RANGE, pointSizes);
    largestPoint_ = pointSizes[1];
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, largestViewport_.data());
}

bool TiledQuadsTechnique::drawsTilesAsPoints(const TileLightLists& lists) const
{
    return !tilesAsQuads_ && largestPoint_ >= static_cast<float>(lists.tileSize) &&
           lists.tilesX * lists.tileSize <= largestViewport_[0] && lists.tilesY * lists.tileSize <= largestViewport_[1];
}

void TiledQuadsTechnique::cullAndUpload(const GpuScene& scene, const FrameTargets& targets)
{
    // The camera as the frame's matrices were made from it (render/scene/GpuFrame.cpp).
    const FrameUniforms& frame = scene.frameUniforms();
    TileCullingView view;
    view.view = frame.view;
    view.fovY = 2.0f * std::atan(frame.projection.y);
    view.nearPlane = frame.projection.z;
    view.farPlane = frame.projection.w;
    view.width = targets.width;
    view.height = targets.height;
    view.tileSize = kDefaultTileSize;
    const TileLightLists& lists = culler_.cull(view, scene.packedLights());

    // Each tile's lights in runs of at most a light batch (one quad each), and the quads
    // bucketed by variant (a counting sort), so that each variant is one instanced draw and
    // the program changes only between buckets.
    const auto forEachQuad = [&](auto&& visit) {
        for (std::size_t tile = 0; tile < lists.tileCount(); ++tile) {
            const TileRange range = lists.tiles[tile];
            for (std::uint32_t done = 0; done < range.count; done += kLightsPerBatch)
                visit(TileQuad{static_cast<std::uint32_t>(tile), range.offset + done,
                               std::min(range.count - done, kLightsPerBatch), 0});
        }
    };
    std::array<std::uint32_t, kVariants> perVariant{};
    forEachQuad([&](const TileQuad& quad) { ++perVariant[variantFor(quad.lightCount)]; });
    variantFirst_[0] = 0;
    for (std::size_t v = 0; v < kVariants; ++v)
        variantFirst_[v + 1] = variantFirst_[v] + perVariant[v];
    drawOrder_.resize(variantFirst_[kVariants]);
    std::array<std::uint32_t, kVariants> cursor{};
    std::copy(variantFirst_.begin(), variantFirst_.end() - 1, cursor.begin());
    forEachQuad([&](const TileQuad& quad) { drawOrder_[cursor[variantFor(quad.lightCount)]++] = quad; });

    gl::uploadGrowing<TileQuad>(tileQuads_, "tile quads", drawOrder_);
    gl::uploadGrowing<std::uint32_t>(lightIndices_, "tile light indices", lists.lightIndices);
}

void TiledQuadsTechnique::drawTiles(const GpuScene& scene, const FrameTargets& targets) const
{
    if (drawOrder_.empty())
        return;
    const TileLightLists& lists = culler_.lists();
    tileQuads_.bindBase(GL_SHADER_STORAGE_BUFFER, kTileQuadsBinding);
    lightIndices_.bindBase(GL_SHADER_STORAGE_BUFFER, kTileLightsBinding);
    const bool points = drawsTilesAsPoints(lists);
    const glm::vec2 viewportSize =
        points ? glm::vec2(static_cast<float>(lists.tilesX * lists.tileSize),
                           static_cast<float>(lists.tilesY * lists.tileSize))
               : glm::vec2(static_cast<float>(targets.width), static_cast<float>(targets.height));
    for (std::size_t v = 0; v < kVariants; ++v) {
        const std::uint32_t tiles = variantFirst_[v + 1] - variantFirst_[v];
        if (tiles == 0)
            continue;
        const gl::Program& program = quads_.variant(ShaderVariant{.lighting = scene.lightingFeatures(),
                                                                  .lights = scene.indexedLightSource(),
                                                                  .maxTileLights = kTileLightBounds[v]});
        program.set(kFirstQuad, variantFirst_[v]);
        program.set(kTilesX, lists.tilesX);
        program.set(kTileSize, lists.tileSize);
        program.set(kViewportSize, viewportSize);
        program.set(kTilesAsPoints, static_cast<int>(points));
        program.use();
        if (points)
            glDrawArraysInstanced(GL_POINTS, 0, 1, static_cast<GLsizei>(tiles));
        else
            glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(tiles));
    }
}

void TiledQuadsTechnique::render(const GpuScene& scene, FrameTargets& targets, FramePasses& passes)
{
    targets.gbuffer.fill(passes);
    // The culling runs on the CPU: this pass's wall time is its cost (with the upload of the
    // lists), its GPU time is near zero.
    passes.run({.name = "cpu-culling"}, [&] { cullAndUpload(scene, targets); });
    passes.run({.name = "global", .target = Resource::LitImage, .state = kCoveredPixels, .sampled = Resource::GBuffer},
               [&] { drawCoveredPixels(global_.variant(scene.lightingFeatures())); });
    // The quads lie at depth 1, so GL_GREATER passes only where a surface was drawn, and the
    // background is never shaded.
    PipelineState lighting = kAddToCoveredPixels;
    // Each tile is one point where the driver draws points of the tile's size (every driver
    // we know of; GL promises only 1 pixel), else a quad of two triangles. A software
    // rasteriser shades each triangle in whole 4x4 blocks, so the blocks the quad's diagonal
    // cuts run the fragment shader twice: 12% more runs with 32-pixel tiles, 25% with 16. A
    // point is one primitive (courtyard, 4096 lights, 1280x720: lighting 125 -> 101 ms,
    // docs/performance.md).
    const TileLightLists& lists = culler_.lists();
    if (drawsTilesAsPoints(lists)) {
        // The viewport spans every tile, so that each point's centre lies inside it: GL may
        // drop a point whose centre is outside (llvmpipe, like many GPUs, draws it anyway,
        // so no test here can tell). The scissor keeps the image's pixels only.
        lighting.viewport = {0, 0, lists.tilesX * lists.tileSize, lists.tilesY * lists.tileSize};
        lighting.scissor = {0, 0, targets.width, targets.height};
        lighting.pointSizeFromShader = true;
    }
    passes.run({.name = "lighting", .target = Resource::LitImage, .state = lighting, .sampled = Resource::GBuffer},
               [&] { drawTiles(scene, targets); });
}

}  // namespace manylights
