// The lighting of one pixel from its cluster's light list (lib/cluster_lists.glsl), which
// clustered.frag, every_tile_lighting.comp and long_list_lighting.comp wrap
// (lib/lighting_stage.glsl), so that clustered's two lighting stages and tiled give the same
// sums in the same order.

// The cluster of a surface in tile `tile`.
uint clusterOfSurface(Surface s, uint tile)
{
    return tile * uint(CLUSTER_SLICES) + sliceOfDepth(viewDepth(s.position), tileDepthRange[tile]);
}

// Part `part` of the list of `cluster` at `pixel`; with `globalTerms` (part 0, a constant at
// every call) first the light-independent terms and, with GLOBAL_LIGHT_LIST, the global lights.
// Loop iterations: CLUSTER_LIST_PART, and GLOBAL_LIGHT_CAPACITY more with GLOBAL_LIGHT_LIST.
vec3 shadeListPixel(ivec2 pixel, Surface s, uint cluster, uint part, bool globalTerms)
{
    vec3 V = viewVector(s.position);
    uint evaluated = 0u;
    vec3 color = globalTerms ? shadeGlobal(s, V) : vec3(0.0);
#ifdef GLOBAL_LIGHT_LIST
    color += shadeGlobalLights(s, V, evaluated);
#endif
    color += shadeClusterListPart(cluster, part, s, V, evaluated);
    recordLightEvaluationsAt(pixel, evaluated);
    return color;
}
