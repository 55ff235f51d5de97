// Binding points of every uniform block, storage buffer, texture unit and image unit the
// shaders use: the one table the shaders (which include this file) and the C++ code
// (render/programs/Bindings.h includes it as C++) both read, so a number cannot drift between them.
// tests/gl/BindingsTest.cpp checks every linked program's interface against it. Written in
// the common subset of GLSL and C++ (const int, no vectors). Two names may share a number
// where no program uses both (each line says which shaders use it).

// Uniform blocks.
const int FRAME_BLOCK_BINDING = 0;         // lib/frame.glsl Frame
const int SHADOWING_BLOCK_BINDING = 1;     // lib/shadows.glsl Shadowing
const int LIGHT_WINDOW_BLOCK_BINDING = 2;  // lib/lights.glsl LightWindow (render/programs/LightBatches.h)
const int ENVIRONMENT_BLOCK_BINDING = 3;   // lib/environment.glsl EnvironmentLight

// Shader storage buffers.
const int LIGHTS_BUFFER_BINDING = 0;                  // lib/lights.glsl Lights
const int LUMINANCE_RESULT_BUFFER_BINDING = 0;        // log_luminance.comp Result
const int TILE_QUADS_BUFFER_BINDING = 1;              // tiled_quads.vert TileQuads
const int VOLUME_LIGHTS_BUFFER_BINDING = 1;           // volume.vert VolumeLights
const int LIGHT_MOTIONS_BUFFER_BINDING = 1;           // pose_lights.comp LightMotions
const int CLUSTER_TILE_DEPTHS_BUFFER_BINDING = 2;     // lib/clusters.glsl ClusterTileDepths
const int CLUSTER_TILE_SLICES_BUFFER_BINDING = 3;     // lib/clusters.glsl ClusterTileSlices
const int TILE_LIGHTS_BUFFER_BINDING = 3;             // tiled_quads.frag TileLights
const int CLUSTER_LIGHT_MASKS_BUFFER_BINDING = 4;     // lib/clusters.glsl ClusterLightMasks
const int CLUSTER_MASK_SUMMARIES_BUFFER_BINDING = 5;  // lib/clusters.glsl ClusterMaskSummaries
const int INSTANCES_BUFFER_BINDING = 8;               // lib/instances.glsl Instances
const int TRANSPARENT_EVALUATIONS_BUFFER_BINDING = 9;  // transparent.frag TransparentEvaluations
const int SSAO_SAMPLES_BUFFER_BINDING = 11;           // ssao.comp SsaoSamples
// The shadow-page pool's own passes (render/shadows/ShadowPool.h), which look no page up.
const int SHADOW_PAGE_MARKS_BUFFER_BINDING = 6;    // lib/shadow_pages.glsl ShadowPageMarks (SHADOW_PAGE_MARKING)
const int SHADOW_CASTER_FACES_BUFFER_BINDING = 6;  // shadow_page.vert CasterFaces
const int SHADOW_CLEAR_RECTS_BUFFER_BINDING = 6;   // shadow_page_clear.vert ClearRects
const int SHADOW_FACE_DRAWS_BUFFER_BINDING = 7;    // shadow_page.vert FaceDraws
// The clustered technique's light lists (render/culling/ClusterLists.h).
const int CLUSTER_LIST_COUNTS_BUFFER_BINDING = 13;   // lib/cluster_lists.glsl, cluster_pairs.comp
const int CLUSTER_LIST_LIGHTS_BUFFER_BINDING = 14;   // lib/cluster_lists.glsl; pair_sort.comp PairLightsIn
const int PAIR_KEYS_IN_BUFFER_BINDING = 15;          // cluster_pairs.comp, pair_sort.comp
const int PAIR_KEYS_OUT_BUFFER_BINDING = 16;         // pair_sort.comp
const int PAIR_LIGHTS_OUT_BUFFER_BINDING = 17;       // pair_sort.comp
const int LIGHT_PAIR_OFFSETS_BUFFER_BINDING = 18;    // cluster_pairs.comp
const int LIGHT_PAIR_CURSORS_BUFFER_BINDING = 19;    // cluster_pairs.comp
const int CLUSTER_LIST_STATUS_BUFFER_BINDING = 20;   // lib/cluster_list_status.glsl
const int SCAN_DATA_BUFFER_BINDING = 21;             // scan.comp; pair_sort.comp Histogram
const int SCAN_PARTIALS_BUFFER_BINDING = 22;         // scan.comp
const int CLUSTER_LIST_FIRSTS_BUFFER_BINDING = 23;   // lib/cluster_lists.glsl
const int CLUSTER_LONG_TILES_BUFFER_BINDING = 24;    // cluster_long_lists.comp, long_list_lighting.comp
const int WIDE_LIGHTS_BUFFER_BINDING = 25;           // cluster_pairs.comp
const int CLUSTER_BOUNDS_BUFFER_BINDING = 26;        // lib/clusters.glsl ClusterBounds (CLUSTER_SURFACE_BOUNDS)
const int CLUSTER_LIST_SPHERES_BUFFER_BINDING = 27;  // lib/cluster_lists.glsl; pair_sort.comp PairSpheresOut
const int LIGHT_TILE_RECORDS_BUFFER_BINDING = 28;    // cluster_pairs.comp
const int PAIRED_LIGHTS_BUFFER_BINDING = 29;         // cluster_pairs.comp
const int GLOBAL_LIGHT_CANDIDATES_BUFFER_BINDING = 30;  // cluster_pairs.comp, global_light_order.comp
const int GLOBAL_LIGHTS_BUFFER_BINDING = 31;          // lib/cluster_lists.glsl; global_light_order.comp
// Shares PAIR_LIGHTS_OUT's number: only pair_sort.comp uses that.
const int GLOBAL_LIGHT_RECORDS_BUFFER_BINDING = 17;   // lib/cluster_lists.glsl; global_light_order.comp
const int ENVIRONMENT_BRIGHT_TEXELS_BUFFER_BINDING = 0;  // environment_prefilter.comp BrightTexels

// Texture units. 0-4 are the G-buffer's targets (render/frame/GBuffer.h: each target's unit).
const int GBUFFER_POSITION_UNIT = 0;  // lib/gbuffer_position.glsl gPositionShininess (seed layout)
const int GBUFFER_SURFACE_UNIT = 0;   // lib/gbuffer_position.glsl gSurface (compact layout)
const int GBUFFER_NORMAL_UNIT = 1;    // lib/gbuffer.glsl gNormal (seed layout)
const int GBUFFER_DIFFUSE_UNIT = 2;   // lib/gbuffer.glsl gDiffuse (seed layout)
const int GBUFFER_SPECULAR_UNIT = 3;  // lib/gbuffer.glsl gSpecular (seed layout)
const int GBUFFER_EMISSIVE_UNIT = 4;  // lib/gbuffer.glsl gEmissive
const int DISPLAY_SOURCE_UNIT = 0;    // display.frag litImage, lib/fxaa_edge.glsl source, log_luminance.comp litImage
const int LUMINANCE_DEPTH_UNIT = 1;   // log_luminance.comp sceneDepth
const int SCENE_DEPTH_UNIT = 5;       // sceneDepth of the compute passes
const int DIFFUSE_MAP_UNIT = 6;       // lib/material.glsl, shadow_depth.frag
const int CLUSTER_LIST_TEXELS_UNIT = 6;  // lib/cluster_lists.glsl clusterListTexels (no material maps there)
const int SPECULAR_MAP_UNIT = 7;      // lib/material.glsl (or the metallic-roughness map)
const int CLUSTER_LIST_SPHERES_UNIT = 7;  // lib/cluster_lists.glsl clusterListSphereTexels (no material maps there)
const int NORMAL_MAP_UNIT = 8;        // lib/material.glsl
const int GLOBAL_LIGHT_TEXELS_UNIT = 8;  // lib/cluster_lists.glsl globalLightTexels (no material maps there)
// lib/cluster_culling.glsl's grid as texels (CLUSTER_GRID_TEXELS): cluster_pairs.comp, which
// has no material maps or shadows.
const int CLUSTER_TILE_DEPTHS_UNIT = 8;
const int CLUSTER_TILE_SLICES_UNIT = 9;
const int CLUSTER_BOUNDS_UNIT = 10;
const int DIRECTIONAL_SHADOW_UNIT = 9;  // lib/shadows.glsl
const int SHADOW_ATLAS_UNIT = 10;       // lib/shadow_pages.glsl: the shadow-page pool's depth atlas
const int SHADOW_TABLES_UNIT = 11;      // lib/shadow_pages.glsl: its page tables
const int OPACITY_MAP_UNIT = 12;        // lib/material.glsl
const int GLOBAL_LIGHT_RECORDS_UNIT = 12;  // lib/cluster_lists.glsl globalLightRecordTexels (no material maps there)
const int AMBIENT_OCCLUSION_UNIT = 13;  // lib/shadows.glsl: the blurred SSAO factor
const int RAW_OCCLUSION_UNIT = 14;      // ssao_blur.comp: the unblurred factor
// Shares RAW_OCCLUSION's number, within the 16 units GL promises: only ssao_blur.comp uses that.
const int ENVIRONMENT_RADIANCE_UNIT = 14;  // lib/environment.glsl: the prefiltered radiance
const int ENVIRONMENT_SOURCE_UNIT = 0;     // environment_prefilter.comp: the map's remainder with its mipmaps
const int EMISSIVE_MAP_UNIT = 15;       // lib/material.glsl
// The 17th and 18th units: GL promises 16 per stage, drivers have 32 (render/programs/LightBatches.h checks).
const int LIGHT_TEXELS_UNIT = 16;  // lib/lights.glsl lightTexels (render/programs/LightBatches.h: light texels)
const int OCCLUSION_MAP_UNIT = 17;  // lib/material.glsl: glTF occlusionTexture
const int ENVIRONMENT_MAP_UNIT = 18;  // lib/environment.glsl: the map itself, level 0 (issue 48)

// Image units.
const int LIGHT_EVALUATIONS_IMAGE_UNIT = 0;  // lib/lighting.glsl (--count-work)
const int IN_RANGE_COUNTS_IMAGE_UNIT = 1;    // in_range.comp
const int OCCLUSION_IMAGE_UNIT = 1;          // ssao.comp, ssao_blur.comp: what they write
const int LIT_IMAGE_UNIT = 2;                // tiled.comp
const int ENVIRONMENT_LEVEL_IMAGE_UNIT = 3;  // environment_prefilter.comp: the level it writes
