// tiled-quads: the screen cut into 16-pixel tiles, the lights culled against each tile on
// the CPU (render/culling/TileCulling.h), and each tile drawn as one point or quad whose fragment
// shader loops over that tile's lights only.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "gl/Buffer.h"
#include "gl/Program.h"
#include "render/culling/TileCulling.h"
#include "render/programs/LightBatches.h"
#include "render/programs/LightingPrograms.h"
#include "render/techniques/Technique.h"

namespace manylights {

// The shader variants: tiles are bucketed by their light count, and a quad with n lights is
// drawn by the variant with the smallest bound ≥ n. Its loop then has a constant trip limit,
// which shader compilers can unroll and schedule for: the classic way this technique kept
// per-tile loops cheap on hardware with weak dynamic loops. The last bound is a light batch
// (render/programs/LightBatches.h): a tile with more lights is drawn as several quads, one per run of
// that many of its lights, added together.
inline constexpr std::array<std::uint32_t, 9> kTileLightBounds = {8, 16, 32, 64, 128, 256, 512, 1024, kLightsPerBatch};

class TiledQuadsTechnique : public Technique {
public:
    explicit TiledQuadsTechnique(const TechniqueOptions& options);
    std::string_view name() const override { return "tiled-quads"; }
    void render(const GpuScene& scene, FrameTargets& targets, FramePasses& passes) override;

    // The last frame's culling result, for tests and statistics.
    const TileLightLists& lastLists() const { return culler_.lists(); }
    // Draws tiles as quads even where the driver draws points of the tile's size (tests: the
    // fallback's image).
    void drawTilesAsQuads(bool quads) { tilesAsQuads_ = quads; }

private:
    static constexpr std::size_t kVariants = kTileLightBounds.size();

    // One instance of a variant's draw: a tile and a run of its lights (std430 uvec4 of
    // shaders/tiled_quads.vert).
    struct TileQuad {
        std::uint32_t tile;
        std::uint32_t firstLight;  // in TileLightLists::lightIndices
        std::uint32_t lightCount;
        std::uint32_t unused;
    };

    // Culls, buckets the tiles by variant and uploads what the quads read.
    void cullAndUpload(const GpuScene& scene, const FrameTargets& targets);
    void drawTiles(const GpuScene& scene, const FrameTargets& targets) const;
    bool drawsTilesAsPoints(const TileLightLists& lists) const;

    LightingProgram global_;
    // Compiled per light-count bucket (ShaderVariant::maxTileLights), the scene's kinds of light
    // and its light source.
    LightingProgram quads_;
    TileCuller culler_;
    // The quads to draw (tiles with lights), grouped by variant: variant v draws
    // drawOrder_[variantFirst_[v] .. variantFirst_[v + 1]).
    std::vector<TileQuad> drawOrder_;
    std::array<std::uint32_t, kVariants + 1> variantFirst_{};
    gl::Buffer tileQuads_;
    gl::Buffer lightIndices_;
    float largestPoint_ = 1.0f;  // pixels
    std::array<GLint, 2> largestViewport_{};
    bool tilesAsQuads_ = false;
};

}  // namespace manylights
