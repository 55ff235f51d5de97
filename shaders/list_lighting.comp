#version 450 core
// Lighting from the light lists of a cluster grid (lib/cluster_lists.glsl), in a compute pass:
// an invocation per pixel, a workgroup per tile.
// - EVERY_TILE: tiled's lighting (render/techniques/TiledTechnique.h), and clustered's under
//   --lighting-stage compute (ClusteredTechnique.h). The workgroups cover the image; each
//   covered pixel stores the global terms, the global lights and part 0 of its cluster's list.
// - otherwise: part `part` (1, 2, ...) of the lists longer than a part, for the clustered and
//   tiled techniques. One workgroup per tile that cluster_long_lists.comp listed (an indirect
//   dispatch: the CPU does not know how many; lib/listed_dispatch.glsl); pixels whose
//   cluster's list is shorter than the part store nothing, the others add the part to the
//   lit image.
// Loop iterations: CLUSTER_LIST_PART, and GLOBAL_LIGHT_CAPACITY more with GLOBAL_LIGHT_LIST (the
// global list, which only EVERY_TILE walks).
#include "lib/bindings.glsl"
#define LIGHTING_IN_COMPUTE 1
#include "lib/light_batch.glsl"
#include "lib/lighting.glsl"
#include "lib/gbuffer.glsl"
#include "lib/clusters.glsl"
// The status before lib/cluster_lists.glsl, which includes it only when counting work: the
// later parts read the number of tiles listed.
#include "lib/cluster_list_status.glsl"
#include "lib/cluster_lists.glsl"
#include "lib/listed_dispatch.glsl"

layout(local_size_x = CLUSTER_TILE_SIZE, local_size_y = CLUSTER_TILE_SIZE) in;
layout(location = CLUSTER_LIST_PART_LOCATION) uniform uint part;
layout(binding = SCENE_DEPTH_UNIT) uniform sampler2D sceneDepth;
layout(binding = LIT_IMAGE_UNIT, rgba32f) uniform image2D litImage;
layout(std430, binding = CLUSTER_LONG_TILES_BUFFER_BINDING) readonly buffer LongListTiles {
    uint longListTile[];
};

void main()
{
#ifdef EVERY_TILE
    uint tile = gl_WorkGroupID.y * clusterTileGrid().x + gl_WorkGroupID.x;
#else
    uint listed = listedGroup();
    if (listed >= longTiles)
        return;
    uint tile = longListTile[listed];
#endif
    uvec2 lo;
    uvec2 hi;
    clusterTilePixels(tile, lo, hi);
    ivec2 pixel = ivec2(lo + gl_LocalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(pixel), hi)) || texelFetch(sceneDepth, pixel, 0).r >= 1.0)
        return;
    Surface s = gbufferSurface(pixel);
    uint cluster = tile * uint(CLUSTER_SLICES) + sliceOfDepth(viewDepth(s.position), tileDepthRange[tile]);
#ifndef EVERY_TILE
    if (clusterListCount[cluster] <= part * uint(CLUSTER_LIST_PART))
        return;
#endif
    vec3 V = viewVector(s.position);
    uint evaluated = 0u;
    // In clustered.frag's order (the global terms, the global lights, the cluster's list), so
    // that clustered's two lighting stages give the same image, bit for bit.
#ifdef EVERY_TILE
    vec3 color = shadeGlobal(s, V);
#else
    vec3 color = vec3(0.0);
#endif
#ifdef GLOBAL_LIGHT_LIST
    color += shadeGlobalLights(s, V, evaluated);
#endif
    color += shadeClusterListPart(cluster, part, s, V, evaluated);
    recordLightEvaluationsAt(pixel, evaluated);
#ifndef EVERY_TILE
    color += imageLoad(litImage, pixel).rgb;
#endif
    imageStore(litImage, pixel, vec4(color, 1.0));
}
