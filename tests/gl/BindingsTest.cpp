// The binding table (shaders/lib/bindings.glsl, render/programs/Bindings.h) against every program the
// renderer links: after frames of every technique with shadows, SSAO, transparency, an
// environment, work counting, every view and the display pass with FXAA and auto-exposure,
// every live program object in the context is asked for its uniform blocks, storage blocks and
// sampler and image uniforms, and each one's binding must be the table's for its name. A resource the table
// does not name fails too, so a new binding cannot bypass it.
#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "GlContextTest.h"
#include "render/Renderer.h"
#include "render/Techniques.h"
#include "render/programs/Bindings.h"
#include "scene/LightSets.h"
#include "scene/SceneLoader.h"

namespace manylights {
namespace {

enum class Kind { UniformBlock, StorageBlock, Sampler, Image };

const char* kindName(Kind kind)
{
    switch (kind) {
    case Kind::UniformBlock: return "uniform block";
    case Kind::StorageBlock: return "storage block";
    case Kind::Sampler: return "sampler";
    case Kind::Image: return "image";
    }
    return "?";
}

// The table, by what the shaders call each resource.
const std::map<std::pair<Kind, std::string>, int>& expectedBindings()
{
    using namespace bindings;
    static const std::map<std::pair<Kind, std::string>, int> table = {
        {{Kind::UniformBlock, "Frame"}, FRAME_BLOCK_BINDING},
        {{Kind::UniformBlock, "Shadowing"}, SHADOWING_BLOCK_BINDING},
        {{Kind::UniformBlock, "LightWindow"}, LIGHT_WINDOW_BLOCK_BINDING},
        {{Kind::UniformBlock, "EnvironmentLight"}, ENVIRONMENT_BLOCK_BINDING},
        {{Kind::StorageBlock, "Lights"}, LIGHTS_BUFFER_BINDING},
        {{Kind::StorageBlock, "Result"}, LUMINANCE_RESULT_BUFFER_BINDING},
        {{Kind::StorageBlock, "TileQuads"}, TILE_QUADS_BUFFER_BINDING},
        {{Kind::StorageBlock, "VolumeLights"}, VOLUME_LIGHTS_BUFFER_BINDING},
        {{Kind::StorageBlock, "LightMotions"}, LIGHT_MOTIONS_BUFFER_BINDING},
        {{Kind::StorageBlock, "ClusterTileDepths"}, CLUSTER_TILE_DEPTHS_BUFFER_BINDING},
        {{Kind::StorageBlock, "ClusterTileSlices"}, CLUSTER_TILE_SLICES_BUFFER_BINDING},
        {{Kind::StorageBlock, "TileLights"}, TILE_LIGHTS_BUFFER_BINDING},
        {{Kind::StorageBlock, "ClusterLightMasks"}, CLUSTER_LIGHT_MASKS_BUFFER_BINDING},
        {{Kind::StorageBlock, "ClusterMaskSummaries"}, CLUSTER_MASK_SUMMARIES_BUFFER_BINDING},
        {{Kind::StorageBlock, "Instances"}, INSTANCES_BUFFER_BINDING},
        {{Kind::StorageBlock, "TransparentEvaluations"}, TRANSPARENT_EVALUATIONS_BUFFER_BINDING},
        {{Kind::StorageBlock, "ShadowPageMarks"}, SHADOW_PAGE_MARKS_BUFFER_BINDING},
        {{Kind::StorageBlock, "CasterFaces"}, SHADOW_CASTER_FACES_BUFFER_BINDING},
        {{Kind::StorageBlock, "ClearRects"}, SHADOW_CLEAR_RECTS_BUFFER_BINDING},
        {{Kind::StorageBlock, "FaceDraws"}, SHADOW_FACE_DRAWS_BUFFER_BINDING},
        {{Kind::StorageBlock, "SsaoSamples"}, SSAO_SAMPLES_BUFFER_BINDING},
        {{Kind::StorageBlock, "ClusterBounds"}, CLUSTER_BOUNDS_BUFFER_BINDING},
        {{Kind::StorageBlock, "ClusterListStatus"}, CLUSTER_LIST_STATUS_BUFFER_BINDING},
        {{Kind::StorageBlock, "ClusterListCounts"}, CLUSTER_LIST_COUNTS_BUFFER_BINDING},
        {{Kind::StorageBlock, "ClusterListFirsts"}, CLUSTER_LIST_FIRSTS_BUFFER_BINDING},
        {{Kind::StorageBlock, "ClusterListLights"}, CLUSTER_LIST_LIGHTS_BUFFER_BINDING},
        {{Kind::StorageBlock, "ClusterListSpheres"}, CLUSTER_LIST_SPHERES_BUFFER_BINDING},
        {{Kind::StorageBlock, "PairSpheresOut"}, CLUSTER_LIST_SPHERES_BUFFER_BINDING},
        {{Kind::StorageBlock, "LightTileRecords"}, LIGHT_TILE_RECORDS_BUFFER_BINDING},
        {{Kind::StorageBlock, "LongListTiles"}, CLUSTER_LONG_TILES_BUFFER_BINDING},
        {{Kind::StorageBlock, "LightPairOffsets"}, LIGHT_PAIR_OFFSETS_BUFFER_BINDING},
        {{Kind::StorageBlock, "LightPairCursors"}, LIGHT_PAIR_CURSORS_BUFFER_BINDING},
        {{Kind::StorageBlock, "WideLights"}, WIDE_LIGHTS_BUFFER_BINDING},
        {{Kind::StorageBlock, "PairedLights"}, PAIRED_LIGHTS_BUFFER_BINDING},
        {{Kind::StorageBlock, "PairKeys"}, PAIR_KEYS_IN_BUFFER_BINDING},
        {{Kind::StorageBlock, "PairLights"}, CLUSTER_LIST_LIGHTS_BUFFER_BINDING},
        {{Kind::StorageBlock, "PairKeysIn"}, PAIR_KEYS_IN_BUFFER_BINDING},
        {{Kind::StorageBlock, "PairLightsIn"}, CLUSTER_LIST_LIGHTS_BUFFER_BINDING},
        {{Kind::StorageBlock, "PairKeysOut"}, PAIR_KEYS_OUT_BUFFER_BINDING},
        {{Kind::StorageBlock, "PairLightsOut"}, PAIR_LIGHTS_OUT_BUFFER_BINDING},
        {{Kind::StorageBlock, "Histogram"}, SCAN_DATA_BUFFER_BINDING},
        {{Kind::StorageBlock, "ScanData"}, SCAN_DATA_BUFFER_BINDING},
        {{Kind::StorageBlock, "ScanPartials"}, SCAN_PARTIALS_BUFFER_BINDING},
        {{Kind::StorageBlock, "ScanTotals"}, CLUSTER_LIST_STATUS_BUFFER_BINDING},
        {{Kind::StorageBlock, "GlobalLightCandidates"}, GLOBAL_LIGHT_CANDIDATES_BUFFER_BINDING},
        {{Kind::StorageBlock, "GlobalLights"}, GLOBAL_LIGHTS_BUFFER_BINDING},
        {{Kind::StorageBlock, "GlobalLightRecords"}, GLOBAL_LIGHT_RECORDS_BUFFER_BINDING},
        {{Kind::StorageBlock, "BrightTexels"}, ENVIRONMENT_BRIGHT_TEXELS_BUFFER_BINDING},
        {{Kind::Sampler, "gPositionShininess"}, GBUFFER_POSITION_UNIT},
        {{Kind::Sampler, "gSurface"}, GBUFFER_SURFACE_UNIT},
        {{Kind::Sampler, "gNormal"}, GBUFFER_NORMAL_UNIT},
        {{Kind::Sampler, "gDiffuse"}, GBUFFER_DIFFUSE_UNIT},
        {{Kind::Sampler, "gSpecular"}, GBUFFER_SPECULAR_UNIT},
        {{Kind::Sampler, "gEmissive"}, GBUFFER_EMISSIVE_UNIT},
        {{Kind::Sampler, "litImage"}, DISPLAY_SOURCE_UNIT},
        {{Kind::Sampler, "source"}, DISPLAY_SOURCE_UNIT},
        {{Kind::Sampler, "surfaceDepth"}, LUMINANCE_DEPTH_UNIT},
        {{Kind::Sampler, "sceneDepth"}, SCENE_DEPTH_UNIT},
        {{Kind::Sampler, "diffuseMap"}, DIFFUSE_MAP_UNIT},
        {{Kind::Sampler, "specularMap"}, SPECULAR_MAP_UNIT},
        {{Kind::Sampler, "normalMap"}, NORMAL_MAP_UNIT},
        {{Kind::Sampler, "directionalShadowMap"}, DIRECTIONAL_SHADOW_UNIT},
        {{Kind::Sampler, "shadowAtlas"}, SHADOW_ATLAS_UNIT},
        {{Kind::Sampler, "shadowTables"}, SHADOW_TABLES_UNIT},
        {{Kind::Sampler, "ambientOcclusionMap"}, AMBIENT_OCCLUSION_UNIT},
        {{Kind::Sampler, "rawOcclusion"}, RAW_OCCLUSION_UNIT},
        {{Kind::Sampler, "emissiveMap"}, EMISSIVE_MAP_UNIT},
        {{Kind::Sampler, "opacityMap"}, OPACITY_MAP_UNIT},
        {{Kind::Sampler, "occlusionMap"}, OCCLUSION_MAP_UNIT},
        {{Kind::Sampler, "lightTexels"}, LIGHT_TEXELS_UNIT},
        {{Kind::Sampler, "clusterListTexels"}, CLUSTER_LIST_TEXELS_UNIT},
        {{Kind::Sampler, "clusterListSphereTexels"}, CLUSTER_LIST_SPHERES_UNIT},
        {{Kind::Sampler, "globalLightTexels"}, GLOBAL_LIGHT_TEXELS_UNIT},
        {{Kind::Sampler, "globalLightRecordTexels"}, GLOBAL_LIGHT_RECORDS_UNIT},
        {{Kind::Sampler, "tileDepthRangeTexels"}, CLUSTER_TILE_DEPTHS_UNIT},
        {{Kind::Sampler, "tileOccupiedSliceTexels"}, CLUSTER_TILE_SLICES_UNIT},
        {{Kind::Sampler, "clusterBoundTexels"}, CLUSTER_BOUNDS_UNIT},
        {{Kind::Sampler, "environmentRadiance"}, ENVIRONMENT_RADIANCE_UNIT},
        {{Kind::Sampler, "environmentSource"}, ENVIRONMENT_SOURCE_UNIT},
        {{Kind::Sampler, "environmentMap"}, ENVIRONMENT_MAP_UNIT},
        {{Kind::Image, "lightEvaluations"}, LIGHT_EVALUATIONS_IMAGE_UNIT},
        {{Kind::Image, "inRangeCounts"}, IN_RANGE_COUNTS_IMAGE_UNIT},
        {{Kind::Image, "rawOcclusion"}, OCCLUSION_IMAGE_UNIT},
        {{Kind::Image, "blurredOcclusion"}, OCCLUSION_IMAGE_UNIT},
        {{Kind::Image, "litImage"}, LIT_IMAGE_UNIT},
        {{Kind::Image, "environmentLevel"}, ENVIRONMENT_LEVEL_IMAGE_UNIT},
    };
    return table;
}

bool isImageType(GLint type)
{
    return type == GL_IMAGE_2D || type == GL_UNSIGNED_INT_IMAGE_2D || type == GL_INT_IMAGE_2D;
}

bool isSamplerType(GLint type)
{
    switch (type) {
    case GL_SAMPLER_2D:
    case GL_SAMPLER_2D_SHADOW:
    case GL_SAMPLER_2D_ARRAY:
    case GL_SAMPLER_2D_ARRAY_SHADOW:
    case GL_SAMPLER_CUBE_MAP_ARRAY_SHADOW:
    case GL_UNSIGNED_INT_SAMPLER_2D:
    case GL_INT_SAMPLER_2D:
    case GL_SAMPLER_BUFFER:
    case GL_UNSIGNED_INT_SAMPLER_BUFFER: return true;
    default: return false;
    }
}

std::string resourceName(GLuint program, GLenum interface, GLuint index)
{
    char name[256] = {};
    glGetProgramResourceName(program, interface, index, sizeof name, nullptr, name);
    return name;
}

// Every (kind, name, binding) of a program's interface.
std::vector<std::tuple<Kind, std::string, int>> bindingsOf(GLuint program)
{
    std::vector<std::tuple<Kind, std::string, int>> found;
    for (const auto& [interface, kind] : {std::pair{GLenum{GL_UNIFORM_BLOCK}, Kind::UniformBlock},
                                          {GLenum{GL_SHADER_STORAGE_BLOCK}, Kind::StorageBlock}}) {
        GLint count = 0;
        glGetProgramInterfaceiv(program, interface, GL_ACTIVE_RESOURCES, &count);
        for (GLint i = 0; i < count; ++i) {
            const GLenum property = GL_BUFFER_BINDING;
            GLint binding = -1;
            glGetProgramResourceiv(program, interface, static_cast<GLuint>(i), 1, &property, 1, nullptr, &binding);
            found.emplace_back(kind, resourceName(program, interface, static_cast<GLuint>(i)), binding);
        }
    }
    GLint uniforms = 0;
    glGetProgramInterfaceiv(program, GL_UNIFORM, GL_ACTIVE_RESOURCES, &uniforms);
    for (GLint i = 0; i < uniforms; ++i) {
        const GLenum properties[2] = {GL_TYPE, GL_LOCATION};
        GLint values[2] = {0, -1};
        glGetProgramResourceiv(program, GL_UNIFORM, static_cast<GLuint>(i), 2, properties, 2, nullptr, values);
        if (!isImageType(values[0]) && !isSamplerType(values[0]))
            continue;
        GLint unit = -1;
        glGetUniformiv(program, values[1], &unit);
        found.emplace_back(isImageType(values[0]) ? Kind::Image : Kind::Sampler,
                           resourceName(program, GL_UNIFORM, static_cast<GLuint>(i)), unit);
    }
    return found;
}

class BindingsTest : public GlContextTest {};

TEST_F(BindingsTest, EveryProgramBindsWhatTheTableSays)
{
    Scene scene = loadSceneFile(MANYLIGHTS_SOURCE_DIR "/tests/scenes/shadows_and_ssao.json");
    // Shadows of every kind, SSAO, a transparent copy of one object with every map and a
    // metallic-roughness copy.
    const std::string textures = MANYLIGHTS_SOURCE_DIR "/tests/scenes/textures/";
    Material glass = scene.materials.front();
    glass.name = "glass";
    glass.opacity = 0.5f;
    glass.alphaMode = AlphaMode::Blend;
    glass.diffuseMap = textures + "brick.png";
    glass.specularMap = textures + "speckle.png";
    glass.normalMap = textures + "bumps.png";
    glass.emissiveMap = textures + "brick.png";
    glass.opacityMap = textures + "speckle.png";
    scene.materials.push_back(glass);
    Object pane = scene.objects.front();
    pane.material = scene.materials.size() - 1;
    pane.transform = glm::translate(pane.transform, glm::vec3(0.0f, 0.5f, 0.0f));
    scene.objects.push_back(pane);
    // And a metallic-roughness copy with its occlusion and metallic-roughness maps.
    Material metal;
    metal.name = "metal";
    metal.model = ShadingModel::MetallicRoughness;
    metal.metallicRoughnessMap = textures + "speckle.png";
    metal.occlusionMap = textures + "speckle.png";
    scene.materials.push_back(metal);
    pane.material = scene.materials.size() - 1;
    pane.transform = glm::translate(pane.transform, glm::vec3(0.0f, 0.5f, 0.0f));
    scene.objects.push_back(pane);
    // And the environment, shown as the background (its prefiltering and background programs).
    scene.environment = Environment{.map = std::string(kStudioEnvironment), .look = {.background = true}};
    std::vector<Light> lights = expandLights(scene);
    // A moving light, for the pass that poses lights on the GPU (render/scene/SceneLights.h).
    lights.front().animation = OrbitAnimation{};

    RendererDesc desc{
        .width = 96,
        .height = 64,
        .shadowLights = 4,
        .display = DisplaySettings{
            .exposure = 1.0f, .toneCurve = ToneCurve::Aces, .srgb = true, .antialiasing = Antialiasing::Fxaa}};
    Renderer renderer(scene, lights, desc);
    renderer.setTime(1.0);
    // The renderer keeps every technique variant it made: their programs stay alive to the end.
    // Without light texels the lights come from the other sources (windows, storage buffer).
    for (const bool count : {false, true}) {
        for (const bool texels : {true, false}) {
            desc.countWork = count;
            desc.lightTexels = texels;
            renderer.apply(desc);
            for (const std::string& name : techniqueNames()) {
                renderer.renderFrame(name, ViewMode::Final);
                if (count)
                    renderer.renderFrame(name, ViewMode::LightCount);
            }
        }
    }
    desc.countWork = false;
    desc.lightTexels = true;
    renderer.apply(desc);
    for (const ViewMode view : {ViewMode::Position, ViewMode::Normal, ViewMode::Volumes, ViewMode::Shadow,
                                ViewMode::Ssao, ViewMode::ShadowResolution})
        renderer.renderFrame("deferred", view);
    renderer.logAverageLuminance();
    // The seed layout's G-buffer targets are read by the programs made for it (counting work:
    // the in-range count's program, made anew for the layout, is alive at the end).
    desc.gbufferLayout = GBufferLayout::Seed;
    desc.countWork = true;
    renderer.apply(desc);
    renderer.renderFrame("deferred", ViewMode::Final);

    int programs = 0;
    std::set<std::pair<Kind, std::string>> seen;
    // Program names are small integers handed out in order: every live program lies below
    // a bound well past what these frames create.
    for (GLuint name = 1; name < 4096; ++name) {
        if (!glIsProgram(name))
            continue;
        GLint linked = GL_FALSE;
        glGetProgramiv(name, GL_LINK_STATUS, &linked);
        if (!linked)
            continue;
        ++programs;
        for (const auto& [kind, resource, binding] : bindingsOf(name)) {
            seen.insert({kind, resource});
            const auto expected = expectedBindings().find({kind, resource});
            if (expected == expectedBindings().end()) {
                ADD_FAILURE() << "program " << name << ": " << kindName(kind) << " '" << resource
                              << "' is not in shaders/lib/bindings.glsl";
                continue;
            }
            EXPECT_EQ(binding, expected->second)
                << "program " << name << ": " << kindName(kind) << " '" << resource << "'";
        }
    }
    EXPECT_GT(programs, 30);
    // Every entry of the table is used by some program these frames made.
    for (const auto& [key, binding] : expectedBindings())
        EXPECT_TRUE(seen.contains(key)) << kindName(key.first) << " '" << key.second << "' (" << binding
                                        << ") was bound by no program";
}

}  // namespace
}  // namespace manylights
