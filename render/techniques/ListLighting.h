// The lighting of a frame from the light lists of a cluster grid (render/culling/ClusterLists.h),
// shared by tiled and clustered: part 0 of every list in one pass over the image, in the
// technique's lighting stage (clustered.frag, or every_tile_lighting.comp: a workgroup per
// tile), then the later parts of the lists longer than a part, each an indirect dispatch of
// long_list_lighting.comp over the tiles that have them, adding to the lit image. Every pass
// is named "lighting". The shaders share one function of a pixel (shaders/lib/list_pixel.glsl),
// so that the stages give the same image, bit for bit.
#pragma once

#include <string>
#include <string_view>

#include "render/culling/ClusterGrid.h"
#include "render/culling/ClusterLists.h"
#include "render/frame/TechniqueOptions.h"
#include "render/programs/LightingPrograms.h"

namespace manylights {

class ListLighting {
public:
    // For lists over grids of `shape`, with programs made for `options` (whose lighting stage
    // is `stage`: tiled lights in compute whatever its options say). Options whose variant
    // marks shadow pages (TechniqueVariant::markShadowPages) make the shadow pool's marking:
    // each pair marks the page its lookup would read, and nothing is stored in the lit image;
    // those that show the shadow resolution (TechniqueVariant::showShadowResolution) store its
    // sums in the lit image instead of light (render/shadows/ShadowResolutionView.h).
    ListLighting(const std::string& label, const TechniqueOptions& options, const ClusterGridShape& shape,
                 LightingStage stage);
    // After ClusterLists::build over `grid`. `alsoWrites`: what the walk writes besides the lit
    // image (the shadow pool's marks), for the passes' barriers.
    void run(const GpuScene& scene, const ClusterGrid& grid, const ClusterLists& lists, FramePasses& passes,
             Resource alsoWrites = Resource::None) const;

private:
    LightingStage stage_;
    std::string_view passName_;  // "lighting", the marking's "shadow marks" or "shadow resolution"
    // Part 0 in the stage, and the later parts (without the global list, which is part 0's); each
    // in the variants of ShaderVariant::listTexels and globalLightList the lists ask for.
    LightingProgram firstPart_;
    LightingProgram laterParts_;
};

}  // namespace manylights
