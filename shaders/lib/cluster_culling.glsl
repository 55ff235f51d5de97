// Which clusters of a tile a light may reach (lib/clusters.glsl's grid), shared by the passes
// that give lights to clusters: the bit masks of cluster_assign.comp (the transparency grid)
// and the light lists of cluster_pairs.comp (the clustered technique). Conservative, like
// lib/culling.glsl: a cluster the light reaches is never left out.
// Needs lib/frame.glsl, lib/clusters.glsl and lib/culling.glsl first.

#ifdef CLUSTER_GRID_TEXELS
// The grid's tiles and surface boxes (lib/clusters.glsl) read as texels of the same buffers
// (render/culling/ClusterGrid.h: texel views): llvmpipe fetches a texel for 8 lanes at once
// where it loads from a storage buffer lane by lane, and the pair passes read a tile's range
// and slices and a box per slice for every light (courtyard, 1280x720, under load: pairs
// 30 -> 21 ms at 16,384 lights, 129 -> 106-112 ms at a million). Where the driver's texture
// buffers are too small for the grid, and on a GPU, the storage buffers.
layout(binding = CLUSTER_TILE_DEPTHS_UNIT) uniform samplerBuffer tileDepthRangeTexels;
layout(binding = CLUSTER_TILE_SLICES_UNIT) uniform usamplerBuffer tileOccupiedSliceTexels;
layout(binding = CLUSTER_BOUNDS_UNIT) uniform samplerBuffer clusterBoundTexels;

vec4 tileSlicingOf(uint tile)
{
    return texelFetch(tileDepthRangeTexels, int(tile));
}

uint tileOccupiedSlicesOf(uint tile)
{
    return texelFetch(tileOccupiedSliceTexels, int(tile)).r;
}

vec4 clusterBoundOf(uint index)
{
    return texelFetch(clusterBoundTexels, int(index));
}
#else
vec4 tileSlicingOf(uint tile)
{
    return tileDepthRange[tile];
}

uint tileOccupiedSlicesOf(uint tile)
{
    return tileOccupiedSlices[tile];
}

#ifdef CLUSTER_SURFACE_BOUNDS
vec4 clusterBoundOf(uint index)
{
    return clusterBounds[index];
}
#endif
#endif

// A light as the culling sees it, in view space.
struct ViewLight {
    vec3 centre;
    float radius;
    bool unbounded;  // reaches every surface: no test can reject it
    vec3 axis;       // a spot's unit axis
    float cosCutoff;  // a spot's cos(cutoff); -2 for point lights
    vec2 logDepthSpan;  // the logs of the view depths of the sphere's near and far side
};

ViewLight viewLight(GpuLight light)
{
    ViewLight view;
    view.radius = light.positionRadius.w;
    view.unbounded = view.radius >= UNBOUNDED_RADIUS;
    view.centre = (frame.view * vec4(light.positionRadius.xyz, 1.0)).xyz;
    view.axis = mat3(frame.view) * light.spotAxisCosCutoff.xyz;
    view.cosCutoff = light.spotAxisCosCutoff.w;
    // Once per light, not per tile: a tile's slices need only a multiply-add of these.
    float depth = -view.centre.z;
    view.logDepthSpan = log(max(vec2(depth - view.radius, depth + view.radius), vec2(1e-30)));
    return view;
}

// Whether the light's sphere and cone can reach the view-space box lo..hi.
bool lightTouchesBox(ViewLight light, vec3 lo, vec3 hi)
{
    return light.unbounded ||
           (sphereTouchesBox(light.centre, light.radius, lo, hi) &&
            coneTouchesSphere(light.centre, light.axis, light.cosCutoff, 0.5 * (lo + hi), 0.5 * length(hi - lo)));
}

// The box around slice k of a tile whose pixels are pixelLo..pixelHi and whose slices span
// `slicing`: the first slice reaches back to the range's start and the last on to its end.
void sliceBox(vec2 pixelLo, vec2 pixelHi, vec4 slicing, uint k, out vec3 lo, out vec3 hi)
{
    float logRatio = 1.0 / slicing.w;
    float zNear = k == 0u ? slicing.x : slicing.x * exp(logRatio * float(k));
    float zFar = k + 1u == uint(CLUSTER_SLICES) ? slicing.y : min(slicing.x * exp(logRatio * float(k + 1u)), slicing.y);
    frustumSectionBox(pixelLo, pixelHi, zNear, max(zFar, zNear), lo, hi);
}

// The box a cluster's light test uses: around its surfaces where the grid keeps their bounds
// (CLUSTER_SURFACE_BOUNDS), else the frustum's section through its tile and slice.
void clusterBox(uint tile, uint k, vec2 pixelLo, vec2 pixelHi, vec4 slicing, out vec3 lo, out vec3 hi)
{
#ifdef CLUSTER_SURFACE_BOUNDS
    uint cluster = tile * uint(CLUSTER_SLICES) + k;
    lo = clusterBoundOf(2u * cluster).xyz;
    hi = clusterBoundOf(2u * cluster + 1u).xyz;
#else
    sliceBox(pixelLo, pixelHi, slicing, k, lo, hi);
#endif
}

// The occupied slices of `tile` (bit k: slice k) whose clusters the light may reach.
// Loop iterations: one per occupied slice within the light's depth span, CLUSTER_SLICES at most.
uint lightSlicesOfTile(ViewLight light, uint tile)
{
    uint slices = tileOccupiedSlicesOf(tile);
    if (slices == 0u)
        return 0u;
    vec4 slicing = tileSlicingOf(tile);
    uvec2 pixelLo;
    uvec2 pixelHi;
    clusterTilePixels(tile, pixelLo, pixelHi);
    vec3 lo;
    vec3 hi;
#ifdef CLUSTER_SURFACE_BOUNDS
    // Boxes around the surfaces are tight enough to test straight away, slice by slice (a test
    // of the tile's whole box first cost more than it saved: courtyard, a million lights, the
    // pairs 171-184 -> 152-162 ms); a grid of one slice per tile (tiled's) has one box.
    if (light.unbounded)
        return slices;
#if CLUSTER_SLICES == 1
    clusterBox(tile, 0u, vec2(pixelLo), vec2(pixelHi), slicing, lo, hi);
    return lightTouchesBox(light, lo, hi) ? slices : 0u;
#endif
#else
    // The whole tile first: most lights that reach its rectangle miss its surfaces' depths.
    frustumSectionBox(vec2(pixelLo), vec2(pixelHi), slicing.x, slicing.y, lo, hi);
    if (!lightTouchesBox(light, lo, hi))
        return 0u;
    if (light.unbounded)
        return slices;
#endif
    // Only the slices within the sphere's depth span: a surface the light reaches lies within
    // its radius in depth too (courtyard, 4096 lights: 15 -> 12 ms, fewer box tests). The
    // lighting pass computes a surface's slice in another program, whose rounding may
    // differ: a hundredth of a slice either way, as cluster_tiles.comp allows for.
    uint kLo = uint(clamp(floor(sliceCoordinateOfLog(light.logDepthSpan.x, slicing) - 0.01), 0.0,
                          float(CLUSTER_SLICES - 1)));
    uint kHi = uint(clamp(floor(sliceCoordinateOfLog(light.logDepthSpan.y, slicing) + 0.01), 0.0,
                          float(CLUSTER_SLICES - 1)));
    slices &= (0xffffffffu >> (31u - kHi)) & ~((1u << kLo) - 1u);
    uint reached = 0u;
    while (slices != 0u) {
        uint k = uint(findLSB(slices));
        slices &= slices - 1u;
        clusterBox(tile, k, vec2(pixelLo), vec2(pixelHi), slicing, lo, hi);
        if (lightTouchesBox(light, lo, hi))
            reached |= 1u << k;
    }
    return reached;
}
