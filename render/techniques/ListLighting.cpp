#include "render/techniques/ListLighting.h"

#include "render/frame/ScreenPasses.h"
#include "render/programs/Locations.h"
#include "render/scene/GpuScene.h"

namespace manylights {

namespace {

LightingProgram firstPartProgram(const std::string& label, const TechniqueOptions& options,
                                 const ClusterGridShape& shape, LightingStage stage)
{
    const gl::Defines defines = CullingVariant{.grid = shape, .lightLists = true}.toDefines();
    if (stage == LightingStage::Compute)
        return LightingProgram(label, {{GL_COMPUTE_SHADER, "every_tile_lighting.comp"}}, options.shaders, defines);
    return LightingProgram(label, {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "clustered.frag"}},
                           options.shaders, defines);
}

LightingProgram laterPartsProgram(const TechniqueOptions& options, const ClusterGridShape& shape)
{
    return LightingProgram("long light lists", {{GL_COMPUTE_SHADER, "long_list_lighting.comp"}}, options.shaders,
                           CullingVariant{.grid = shape, .lightLists = true}.toDefines());
}

}  // namespace

ListLighting::ListLighting(const std::string& label, const TechniqueOptions& options, const ClusterGridShape& shape,
                           LightingStage stage)
    : stage_(stage),
      passName_(options.shaders.markShadowPages        ? "shadow marks"
                : options.shaders.showShadowResolution ? "shadow resolution"
                                                       : "lighting"),
      firstPart_(firstPartProgram(label, options, shape, stage)),
      laterParts_(laterPartsProgram(options, shape))
{
}

void ListLighting::run(const GpuScene& scene, const ClusterGrid& grid, const ClusterLists& lists, FramePasses& passes,
                       Resource alsoWrites) const
{
    // Lists name lights by index, so the lights are read by index.
    const LightSource source = scene.indexedLightSource();
    const ShaderVariant key{.lighting = scene.lightingFeatures(),
                            .lights = source,
                            .listTexels = lists.readsTexels(),
                            .globalLightList = lists.hasGlobalList()};
    const gl::Program& first = firstPart_.variant(key);
    const LightBatch allLights{0, static_cast<std::uint32_t>(scene.lightCount())};
    Pass pass = lightBatchPass(allLights, Resource::LightGrid);
    // The lists may be read as texels (GL_TEXTURE_FETCH_BARRIER_BIT after the list passes'
    // storage writes, not only GL_SHADER_STORAGE_BARRIER_BIT).
    pass.sampled = pass.sampled | Resource::LightGrid;
    pass.writes = pass.writes | alsoWrites;
    pass.name = passName_;
    runLightingPass(passes, stage_, pass, first, static_cast<GLuint>(grid.gridWidth()),
                    static_cast<GLuint>(grid.gridHeight()), [&] {
                        scene.bindLightSource(source, allLights);
                        grid.bind();
                        lists.bind();
                    });
    if (lists.laterParts() == 0)
        return;
    const gl::Program& later = laterParts_.variant(ShaderVariant{
        .lighting = key.lighting, .lights = source, .listTexels = key.listTexels, .globalLightList = false});
    Pass laterPass = computeLightingPass(pass);
    laterPass.indirect = Resource::LightGrid;
    for (std::uint32_t part = 1; part <= lists.laterParts(); ++part)
        passes.run(laterPass, [&] {
            grid.bind();
            lists.bind();
            later.set(locations::CLUSTER_LIST_PART_LOCATION, part);
            later.use();
            lists.dispatchOverLongListTiles();
        });
}

}  // namespace manylights
