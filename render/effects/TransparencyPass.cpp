#include "render/effects/TransparencyPass.h"
#include "render/programs/Bindings.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "render/scene/GpuScene.h"

namespace manylights {

namespace {

constexpr GLuint kEvaluationsBinding = bindings::TRANSPARENT_EVALUATIONS_BUFFER_BINDING;
// Depth slices of the transparent objects' grid (render/culling/ClusterGrid.h): the clustered
// technique's 8. Measured on scenes/glass.json at 1280x720 (docs/transparency.md): 16 and 32
// slices leave the draws as they are (the lights near a pane or a drop reach its whole depth)
// and make the grid dearer (66-92 ms for 8, 102-105 for 16, 170-175 for 32).
constexpr int kTransparentGridSlices = kClusterSlices;

// The view depths of a transparent item's world bounds (its box's centre depth ± its extent
// along the view axis), widened so that rounding cannot put a surface of it outside, and
// clipped to the view's depth.
glm::vec2 depthSpan(const Bounds& bounds, const FrameUniforms& frame)
{
    const float middle = glm::dot(0.5f * (bounds.min + bounds.max) - glm::vec3(frame.eye), glm::vec3(frame.viewAxis));
    const float reach = glm::dot(glm::abs(glm::vec3(frame.viewAxis)), 0.5f * (bounds.max - bounds.min));
    const float nearPlane = frame.projection.z;
    const float farPlane = frame.projection.w;
    return {std::max((middle - reach) * 0.99f, nearPlane), std::min((middle + reach) * 1.01f, farPlane)};
}

// A transparent item whose depth span lies (partly) within the view's depth.
struct ItemInView {
    Bounds bounds;   // world space
    glm::vec2 span;  // depthSpan(bounds), not empty
};

// The transparent items within the view's depth: the others are wholly in front of the near
// plane or beyond the far plane.
std::vector<ItemInView> itemsInView(const std::vector<Bounds>& objects, const FrameUniforms& frame)
{
    std::vector<ItemInView> items;
    for (const Bounds& bounds : objects)
        if (const glm::vec2 span = depthSpan(bounds, frame); span.x < span.y)
            items.push_back({bounds, span});
    return items;
}

// Per tile of the grid, the union of the depth spans of the items whose world bounds may
// cover it on screen: the rectangle around the box's projected corners, widened by a tile;
// every tile when a corner lies at or behind the eye plane (the projection is not bounded
// there). Tiles no item covers get an empty range.
std::vector<glm::vec2> tileDepthRanges(const std::vector<ItemInView>& items, const FrameUniforms& frame,
                                       int tilesAcross, int tilesDown)
{
    std::vector<glm::vec2> ranges(static_cast<std::size_t>(tilesAcross * tilesDown),
                                  glm::vec2(std::numeric_limits<float>::max(), 0.0f));
    const glm::vec2 viewport(frame.viewport.x, frame.viewport.y);
    for (const auto& [bounds, span] : items) {
        glm::vec2 lo(std::numeric_limits<float>::max());
        glm::vec2 hi(-std::numeric_limits<float>::max());
        bool behindEye = false;
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 p((corner & 1) ? bounds.max.x : bounds.min.x, (corner & 2) ? bounds.max.y : bounds.min.y,
                              (corner & 4) ? bounds.max.z : bounds.min.z);
            const glm::vec4 clip = frame.viewProjection * glm::vec4(p, 1.0f);
            if (!(clip.w > 0.0f)) {
                behindEye = true;
                break;
            }
            const glm::vec2 pixel = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * viewport;
            lo = glm::min(lo, pixel);
            hi = glm::max(hi, pixel);
        }
        int x0 = 0, y0 = 0, x1 = tilesAcross - 1, y1 = tilesDown - 1;
        if (!behindEye) {
            const auto tile = [](float pixel, int tiles) {
                return std::clamp(static_cast<int>(std::floor(pixel / kClusterTileSize)), 0, tiles - 1);
            };
            if (hi.x < 0.0f || hi.y < 0.0f || lo.x > viewport.x || lo.y > viewport.y)
                continue;  // off screen
            x0 = std::max(tile(lo.x, tilesAcross) - 1, 0);
            y0 = std::max(tile(lo.y, tilesDown) - 1, 0);
            x1 = std::min(tile(hi.x, tilesAcross) + 1, tilesAcross - 1);
            y1 = std::min(tile(hi.y, tilesDown) + 1, tilesDown - 1);
        }
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                glm::vec2& range = ranges[static_cast<std::size_t>(y * tilesAcross + x)];
                range = {std::min(range.x, span.x), std::max(range.y, span.y)};
            }
    }
    return ranges;
}

}  // namespace

TransparencyPass::TransparencyPass(const TechniqueVariant& technique)
    : technique_(technique),
      // The grid's shape is every variant's; the every-light variant includes no grid.
      programs_("transparency", {{GL_VERTEX_SHADER, "mesh.vert"}, {GL_FRAGMENT_SHADER, "transparent.frag"}}, technique,
                CullingVariant{.grid = ClusterGridShape{.slices = kTransparentGridSlices}}.toDefines()),
      evaluations_("transparent light evaluations", sizeof(std::uint32_t), nullptr,
                   GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT)
{
}

void TransparencyPass::run(const GpuScene& scene, FrameTargets& targets, FramePasses& passes, bool everyLight)
{
    lastEvaluations_ = 0;
    if (!scene.hasTransparentObjects())
        return;
    const FrameUniforms& frame = scene.frameUniforms();
    const std::vector<ItemInView> items = itemsInView(scene.transparentWorldBounds(), frame);
    if (items.empty())
        return;  // nothing transparent within the view's depth
    const auto lightCount = static_cast<std::uint32_t>(scene.lightCount());
    const std::vector<LightBatch> batches =
        everyLight ? lightBatches(lightCount)
                   : lightBatches(lightCount,
                                  ClusterGrid::lightsPerBatch(targets.width, targets.height, kTransparentGridSlices));
    // One grid build serves every layer when the lights are one batch.
    const bool gridPerLayer = !everyLight && batches.size() > 1;
    const Pass gridPass = ClusterGrid::assignPass("transparency grid");
    if (!everyLight)
        passes.run(gridPass, [&] {
            if (!grid_)
                grid_ = std::make_unique<ClusterGrid>(technique_.gbufferLayout,
                                                      ClusterGridShape{.slices = kTransparentGridSlices});
            grid_->resize(targets.width, targets.height, batches.front().size());
            grid_->coverDepthRanges(tileDepthRanges(items, frame, grid_->gridWidth(), grid_->gridHeight()));
            if (!gridPerLayer)
                grid_->assignLights(batches.front());
        });
    if (technique_.countWork) {
        const std::uint32_t zero = 0;
        evaluations_.update(0, sizeof zero, &zero);
    }
    // Depth-tested against the opaque surfaces, never written; premultiplied over.
    const Resource counted = technique_.countWork ? Resource::WorkCounts : Resource::None;
    const Pass drawPass{.name = "transparency",
                        .target = Resource::LitImage,
                        .state = {.keepDepth = true, .blend = Blend::PremultipliedOver},
                        .storage = (everyLight ? Resource::None : Resource::LightGrid) | counted,
                        .writes = counted};
    for (const GpuScene::TransparentLayer& layer : scene.transparentLayersBackToFront()) {
        for (const LightBatch& batch : batches) {
            if (gridPerLayer)
                passes.run(gridPass, [&] { grid_->assignLights(batch); });
            passes.run(drawPass, [&] {
                if (!everyLight)
                    grid_->bind();
                if (technique_.countWork)
                    evaluations_.bindBase(GL_SHADER_STORAGE_BUFFER, kEvaluationsBinding);
                scene.drawTransparentLayer(layer, [&](MaterialVariant variant) -> const gl::Program& {
                    const gl::Program& program = programs_.variant(ShaderVariant{.lighting = scene.lightingFeatures(),
                                                                                 .lights = scene.indexedLightSource(),
                                                                                 .material = variant,
                                                                                 .everyLight = everyLight});
                    setLightBatch(program, batch);
                    return program;
                });
            });
        }
    }
    if (technique_.countWork) {
        // The count is read back: the frame's passes are done first.
        passes.finish();
        std::uint32_t count = 0;
        evaluations_.read(0, sizeof count, &count);
        lastEvaluations_ = count;
    }
}

}  // namespace manylights
