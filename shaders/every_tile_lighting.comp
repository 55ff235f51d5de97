#version 450 core
// Lighting from the light lists of a cluster grid in a compute pass over the whole image, a
// workgroup per tile and an invocation per pixel: tiled's lighting
// (render/techniques/TiledTechnique.h), and clustered's under --lighting-stage compute
// (ClusteredTechnique.h). Each covered pixel stores the global terms, the global lights and
// part 0 of its cluster's list (lib/list_pixel.glsl, as clustered.frag);
// long_list_lighting.comp adds the later parts.
#include "lib/bindings.glsl"
#define LIGHTING_IN_COMPUTE 1
#include "lib/light_batch.glsl"
#include "lib/lighting.glsl"
#include "lib/gbuffer.glsl"
#include "lib/clusters.glsl"
#include "lib/cluster_lists.glsl"
#include "lib/lighting_stage.glsl"
#include "lib/list_pixel.glsl"

layout(local_size_x = CLUSTER_TILE_SIZE, local_size_y = CLUSTER_TILE_SIZE) in;

void main()
{
    uint tile = gl_WorkGroupID.y * clusterTileGrid().x + gl_WorkGroupID.x;
    uvec2 lo;
    uvec2 hi;
    clusterTilePixels(tile, lo, hi);
    ivec2 pixel = ivec2(lo + gl_LocalInvocationID.xy);
    if (any(greaterThanEqual(uvec2(pixel), hi)) || !isLitPixel(pixel))
        return;
    Surface s = gbufferSurface(pixel);
    storeLitPixel(pixel, shadeListPixel(pixel, s, clusterOfSurface(s, tile), 0u, true), false);
}
