// Uniform locations that the C++ code sets by number (gl::Program::set) in the shaders whose
// numbers used to be written twice: the one table the shaders (which include this file) and
// the C++ code (render/programs/Locations.h includes it as C++) both read. Written in the common
// subset of GLSL and C++ (const int). Numbers are per program: two names share one only where
// no program has both (each line says which shaders use it).

// lib/material.glsl (render/scene/DrawList.cpp binds a material's maps). The transforms are mat3x2,
// two locations each, after the light batch's location 40 (render/programs/LightBatches.h).
const int MATERIAL_NORMAL_SCALE_LOCATION = 15;
const int MATERIAL_METALLIC_ROUGHNESS_LOCATION = 16;
const int DIFFUSE_UV_TRANSFORM_LOCATION = 50;  // also shadow_depth.frag's
const int SPECULAR_UV_TRANSFORM_LOCATION = 53;  // also the metallic-roughness map's
const int NORMAL_UV_TRANSFORM_LOCATION = 56;
const int EMISSIVE_UV_TRANSFORM_LOCATION = 59;
const int OPACITY_UV_TRANSFORM_LOCATION = 62;
const int OCCLUSION_UV_TRANSFORM_LOCATION = 65;

// lib/revolution.glsl and lib/instances.glsl (issue 6's range), for mesh.vert and
// shadow_depth.vert.
const int REVOLUTION_ENABLED_LOCATION = 30;
const int REVOLUTION_SHAPE_LOCATION = 31;
const int REVOLUTION_SPEED_LOCATION = 32;
const int INSTANCE_BASE_LOCATION = 33;

// shadow_depth.vert (render/effects/ShadowMaps.cpp).
const int LIGHT_VIEW_PROJECTION_LOCATION = 20;
// shadow_page.vert (render/shadows/ShadowPool.cpp): the first (caster, face) pair of a draw.
const int SHADOW_CASTER_FACE_BASE_LOCATION = 63;

// pose_lights.comp (render/scene/SceneLights.cpp).
const int POSE_TIME_LOCATION = 0;
const int POSE_MOTION_COUNT_LOCATION = 1;

// tiled_quads.vert (render/techniques/TiledQuadsTechnique.cpp).
const int TILE_FIRST_QUAD_LOCATION = 0;
const int TILES_X_LOCATION = 1;
const int TILE_SIZE_LOCATION = 2;
const int TILE_VIEWPORT_SIZE_LOCATION = 3;
const int TILES_AS_POINTS_LOCATION = 4;

// lib/light_batch.glsl, in every program that walks a batch of lights
// (render/programs/LightBatches.cpp).
const int LIGHT_BATCH_LOCATION = 40;
// lib/light_tiles.glsl, in the programs that walk a wide light's tiles by bands
// (render/culling/LightTiles.cpp, ClusterLists.cpp).
const int LIGHT_TILE_ROWS_PER_BAND_LOCATION = 41;

// display.frag (render/effects/DisplayPass.cpp).
const int DISPLAY_EXPOSURE_SCALE_LOCATION = 0;

// ssao.comp (render/effects/Ssao.cpp).
const int SSAO_PARAMS_LOCATION = 20;

// scan.comp (render/culling/GpuScan.cpp).
const int SCAN_COUNT_LOCATION = 50;
const int SCAN_TOTAL_INDEX_LOCATION = 51;

// cluster_pairs.comp and cluster_mask_lists.comp (render/culling/ClusterLists.cpp).
const int CLUSTER_PAIR_LIGHT_COUNT_LOCATION = 52;
const int CLUSTER_PAIR_GLOBAL_TILES_LOCATION = 53;
const int CLUSTER_PAIR_CAPACITY_LOCATION = 54;
const int CLUSTER_MASK_CAPACITY_LOCATION = 54;  // cluster_mask_lists.comp's pair capacity
const int CLUSTER_PAIR_GLOBAL_PLANNED_LOCATION = 60;
const int CLUSTER_MASK_WORDS_LOCATION = 61;
const int CLUSTER_MASK_CLUSTERS_LOCATION = 62;

// pair_sort.comp (render/culling/ClusterLists.cpp).
const int PAIR_SORT_SHIFT_LOCATION = 55;
const int PAIR_SORT_CHUNKS_LOCATION = 56;
const int PAIR_SORT_CAPACITY_LOCATION = 57;

// long_list_lighting.comp (render/techniques/ListLighting.cpp).
const int CLUSTER_LIST_PART_LOCATION = 58;
