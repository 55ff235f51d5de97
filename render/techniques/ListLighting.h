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

// What the walk of the lists does with each (pixel, light) pair: shades it into the lit
// image, or marks the shadow page its lookup would read (render/shadows/ShadowPool.h: the
// programs built with SHADOW_PAGE_MARKING, which store nothing in the lit image).
enum class ListWalk { Shade, MarkShadowPages };

class ListLighting {
public:
    // For lists over grids of `shape`, with programs made for `options` (whose lighting stage
    // is `stage`: tiled lights in compute whatever its options say) to do `walk`.
    ListLighting(const std::string& label, const TechniqueOptions& options, const ClusterGridShape& shape,
                 LightingStage stage, ListWalk walk = ListWalk::Shade);
    // After ClusterLists::build over `grid`. `alsoWrites`: what the walk writes besides the lit
    // image (the shadow pool's marks), for the passes' barriers.
    void run(const GpuScene& scene, const ClusterGrid& grid, const ClusterLists& lists, FramePasses& passes,
             Resource alsoWrites = Resource::None) const;

private:
    LightingStage stage_;
    std::string_view passName_;  // "lighting", or the marking's "shadow marks"
    // Part 0 in the stage, and the later parts (without the global list, which is part 0's); each
    // in the variants of ShaderVariant::listTexels and globalLightList the lists ask for.
    LightingProgram firstPart_;
    LightingProgram laterParts_;
};

}  // namespace manylights
