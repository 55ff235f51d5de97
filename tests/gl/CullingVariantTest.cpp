// The culling programs' key (render/culling/CullingVariant.h): the #defines each of its
// dimensions gives, as the shaders test them (cluster_pairs.comp's runs,
// lib/cluster_list_status.glsl's #ifdef GLOBAL_LIGHT_CAPACITY), and one program per key in
// the cache. That the programs built from it cull correctly is the list tests' work
// (MaskedListsTest, LongListTilesTest, GlobalLightOrderTest, GpuScanTest and the images).
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>
#include <string>

#include "GlContextTest.h"
#include "render/culling/ClusterLists.h"
#include "render/culling/CullingVariant.h"
#include "render/programs/ProgramVariants.h"

namespace manylights {
namespace {

// The value `defines` gives `name`, if any.
std::optional<std::string> valueOf(const gl::Defines& defines, const std::string& name)
{
    const auto found =
        std::find_if(defines.begin(), defines.end(), [&](const auto& define) { return define.first == name; });
    return found == defines.end() ? std::nullopt : std::optional(found->second);
}

gl::Defines pairDefines(bool wide, PairRun run)
{
    return CullingVariant{.grid = kClusteredGridShape, .lightTiles = wide, .globalLights = true, .pairRun = run}
        .toDefines();
}

TEST(CullingVariant, PairRunsEmitWhereTheirPairsAreWritten)
{
    // The narrow lights count, or set their mask bits as they count; the wide lights set
    // theirs in a run of their own, which emits.
    EXPECT_EQ(valueOf(pairDefines(false, PairRun::Count), "EMIT_PAIRS"), "0");
    EXPECT_EQ(valueOf(pairDefines(false, PairRun::Write), "EMIT_PAIRS"), "1");
    EXPECT_EQ(valueOf(pairDefines(false, PairRun::Mask), "EMIT_PAIRS"), "0");
    EXPECT_EQ(valueOf(pairDefines(true, PairRun::Count), "EMIT_PAIRS"), "0");
    EXPECT_EQ(valueOf(pairDefines(true, PairRun::Write), "EMIT_PAIRS"), "1");
    EXPECT_EQ(valueOf(pairDefines(true, PairRun::Mask), "EMIT_PAIRS"), "1");
    EXPECT_TRUE(valueOf(pairDefines(false, PairRun::Mask), "CLUSTER_MASKS"));
    EXPECT_FALSE(valueOf(pairDefines(false, PairRun::Write), "CLUSTER_MASKS"));
    // The wide lights' programs take a workgroup per light.
    EXPECT_TRUE(valueOf(pairDefines(true, PairRun::Count), "WIDE_LIGHTS"));
    EXPECT_TRUE(valueOf(pairDefines(true, PairRun::Count), "LIGHT_TILE_LANES"));
    EXPECT_FALSE(valueOf(pairDefines(false, PairRun::Count), "WIDE_LIGHTS"));
    EXPECT_FALSE(valueOf(pairDefines(false, PairRun::Count), "LIGHT_TILE_LANES"));
}

TEST(CullingVariant, GlobalLightCapacityOnlyWhereTheGlobalListIsUsed)
{
    // lib/cluster_list_status.glsl declares the global list's part of the status by it.
    EXPECT_FALSE(valueOf(CullingVariant{.grid = kClusteredGridShape}.toDefines(), "GLOBAL_LIGHT_CAPACITY"));
    EXPECT_EQ(valueOf(CullingVariant{.globalLights = true}.toDefines(), "GLOBAL_LIGHT_CAPACITY"),
              std::to_string(kGlobalLightCapacity));
    const gl::Defines lists = CullingVariant{.grid = kClusteredGridShape, .lightLists = true}.toDefines();
    EXPECT_EQ(valueOf(lists, "GLOBAL_LIGHT_CAPACITY"), std::to_string(kGlobalLightCapacity));
    EXPECT_EQ(valueOf(lists, "CLUSTER_LIST_PART"), std::to_string(kClusterListPart));
    EXPECT_EQ(valueOf(lists, "CLUSTER_SURFACE_BOUNDS"), "1");
}

class CullingVariantTest : public GlContextTest {};

TEST_F(CullingVariantTest, EachKeyCompilesOnceToItsOwnProgram)
{
    const ProgramVariants<CullingVariant> programs("pair sort", {{GL_COMPUTE_SHADER, "pair_sort.comp"}});
    const gl::Program& count = programs.variant({.sortPass = SortPass::Count});
    const gl::Program& scatter = programs.variant({.sortPass = SortPass::Scatter});
    EXPECT_NE(count.id(), 0u);
    EXPECT_NE(count.id(), scatter.id());
    EXPECT_EQ(&programs.variant({.sortPass = SortPass::Count}), &count);
    EXPECT_EQ(&programs.variant({.sortPass = SortPass::Scatter}), &scatter);
}

}  // namespace
}  // namespace manylights
