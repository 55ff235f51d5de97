// The clustered technique's light lists (render/culling/ClusterLists.h), read by its lighting passes:
// per cluster of lib/clusters.glsl's grid, the lights that may reach it, in the order of the
// lights (sorted by cluster, stably). A list is walked in parts of CLUSTER_LIST_PART lights,
// the most one invocation may walk within render/programs/LightBatches.h's bound: part 0 by the
// lighting pass over the whole image, the later parts of long lists by passes over their
// tiles only (long_list_lighting.comp).
//
// Each listed light gets a finer test per pixel before it is shaded: whether the pixel's
// surface lies in the light's sphere, the same test as lib/lighting.glsl's lightReach, with its
// lightDistance (so it only skips pairs whose A · S is zero). A cluster is a tile of pixels by
// a depth slice; a light far smaller than that (the courtyard at a million lights: ranges of
// 0.1 to 0.2 m, a few pixels) reaches few of its pixels. The lists carry each light's sphere beside its index
// (pair_sort.comp gathers them), so the test costs one fetch, in list order, and a length;
// the light's index and the rest of it are fetched only for the lights that pass. Only those
// are counted as evaluated (--count-work); the entries walked are counted too, as
// cluster_list_visits.
//
// Before its cluster's list, a pixel walks the global list: the lights whose screen rectangle
// covers most of the grid (cluster_pairs.comp), which would be in nearly every list, in the
// lights' order (global_light_order.comp). They have no pairs: on LearnOpenGL's scene, where
// every light reaches every pixel, the pairs were 5.3 million at 512 lights, and writing and
// sorting them cost more than the lighting (docs/techniques.md). Each global light is tested
// the same way, and carries its whole record, not only its sphere: a light in reach costs the
// three fetches more that deferred's loop makes, not an index and four (its index is read only
// for a shadow map). A pixel so sums its global lights, then its cluster's, each in the
// lights' order: one order on every run, though not forward's where a pixel has both.
// Needs lib/lighting.glsl and lib/clusters.glsl first.

#ifdef COUNT_WORK
#include "lib/cluster_list_status.glsl"
#endif
layout(std430, binding = CLUSTER_LIST_COUNTS_BUFFER_BINDING) readonly buffer ClusterListCounts {
    uint clusterListCount[];
};
layout(std430, binding = CLUSTER_LIST_FIRSTS_BUFFER_BINDING) readonly buffer ClusterListFirsts {
    uint clusterListFirst[];
};
#ifdef CLUSTER_LIST_TEXELS
// The lists' lights as R32UI texels and their spheres as RGBA32F texels (render/culling/ClusterLists.h):
// llvmpipe fetches a texel for 8 lanes at once where it loads from a storage buffer lane by
// lane, and every visit of a list entry reads one (LearnOpenGL's scene at 512 lights, where
// every light is in every list: lighting 512-538 -> 478-492 ms). Where the driver's texture
// buffers are too small for the lists, the storage buffers.
layout(binding = CLUSTER_LIST_TEXELS_UNIT) uniform usamplerBuffer clusterListTexels;
layout(binding = CLUSTER_LIST_SPHERES_UNIT) uniform samplerBuffer clusterListSphereTexels;

uint clusterListLight(uint entry)
{
    return texelFetch(clusterListTexels, int(entry)).r;
}

vec4 clusterListSphere(uint entry)
{
    return texelFetch(clusterListSphereTexels, int(entry));
}

layout(binding = GLOBAL_LIGHT_TEXELS_UNIT) uniform usamplerBuffer globalLightTexels;
layout(binding = GLOBAL_LIGHT_RECORDS_UNIT) uniform samplerBuffer globalLightRecordTexels;

uint globalLight(uint entry)
{
    return texelFetch(globalLightTexels, int(entry)).r;
}

vec4 globalLightSphere(uint entry)
{
    return texelFetch(globalLightRecordTexels, int(entry) * 4);
}

// The rest of the global light whose sphere globalLightSphere() fetched.
GpuLight globalLightRecord(uint entry, vec4 positionRadius)
{
    return lightFromTexels(globalLightRecordTexels, int(entry) * 4, positionRadius);
}
#else
layout(std430, binding = CLUSTER_LIST_LIGHTS_BUFFER_BINDING) readonly buffer ClusterListLights {
    uint clusterListLights[];
};
layout(std430, binding = CLUSTER_LIST_SPHERES_BUFFER_BINDING) readonly buffer ClusterListSpheres {
    vec4 clusterListSpheres[];
};

uint clusterListLight(uint entry)
{
    return clusterListLights[entry];
}

vec4 clusterListSphere(uint entry)
{
    return clusterListSpheres[entry];
}

layout(std430, binding = GLOBAL_LIGHTS_BUFFER_BINDING) readonly buffer GlobalLights {
    uint globalLights[];
};
layout(std430, binding = GLOBAL_LIGHT_RECORDS_BUFFER_BINDING) readonly buffer GlobalLightRecords {
    GpuLight globalLightRecords[];
};

uint globalLight(uint entry)
{
    return globalLights[entry];
}

vec4 globalLightSphere(uint entry)
{
    return globalLightRecords[entry].positionRadius;
}

GpuLight globalLightRecord(uint entry, vec4 positionRadius)
{
    GpuLight light = globalLightRecords[entry];
    light.positionRadius = positionRadius;
    return light;
}
#endif

// The global list, shaded at a surface: every pixel walks it before part 0 of its cluster's
// list, in programs built with GLOBAL_LIGHT_LIST (frames that have one, ClusterLists.h). Loop
// iterations: GLOBAL_LIGHT_CAPACITY at most (render/culling/ClusterLists.h counts both walks
// against the loop bound). Each entry is tested and shaded in one pass, not in chunks as the
// cluster's list below (not measured for the global list: on LearnOpenGL's scene, where every
// light reaches every pixel, a chunk's test first could only add a second walk).
vec3 shadeGlobalLights(Surface s, vec3 V, inout uint evaluated)
{
    // After the list's last possible entry: its length (global_light_order.comp).
    uint count = globalLight(uint(GLOBAL_LIGHT_CAPACITY));
    vec3 color = vec3(0.0);
#ifdef COUNT_WORK
    if (count > 0u)
        atomicAdd(listVisits, count);
#endif
    for (uint i = 0u; i < count; ++i) {
        vec4 positionRadius = globalLightSphere(i);
        if (lightDistance(positionRadius.xyz, s.position) < positionRadius.w) {
            color += shadeLocalLight(globalLight(i), globalLightRecord(i, positionRadius), s, V);
            ++evaluated;
        }
    }
    return color;
}

// The list entries whose reach test one pass of the walk makes before it shades those that
// passed: the bits of a uint.
const uint REACH_CHUNK = 32u;

// Part `part` of the cluster's list, shaded at a surface. Loop iterations: 2 CLUSTER_LIST_PART
// (each entry tested once and shaded at most once) and one per REACH_CHUNK entries.
//
// The walk tests a chunk of entries first, keeping those that reach the surface as bits, and
// then shades the lights of the bits set, in list order. Not a test and a shading per entry:
// llvmpipe runs 8 pixels in lock step and runs an if's body under a mask whether or not any of
// its lanes takes it, so every entry walked cost a whole shading, reached or not; a loop it
// leaves once no lane is left in it, so this costs a shading per light that reaches one of the
// 8 pixels, and one per chunk (courtyard, a million lights, 1280x720, where 173 entries are
// walked per light that reaches a pixel: lighting 200 -> 82-90 ms under load; 16,384 lights
// 83 -> 77-84 ms). The sum runs in the same order: the same image, bit for bit.
vec3 shadeClusterListPart(uint cluster, uint part, Surface s, vec3 V, inout uint evaluated)
{
    uint count = clusterListCount[cluster];
    uint first = clusterListFirst[cluster];
    uint begin = part * uint(CLUSTER_LIST_PART);
    uint end = min(count, begin + uint(CLUSTER_LIST_PART));
    vec3 color = vec3(0.0);
#ifdef COUNT_WORK
    if (end > begin)
        atomicAdd(listVisits, end - begin);
#endif
#ifdef BRANCH_ON_REACH
    // The GPU profile's walk: each entry tested and, where it reaches, shaded, in list order (the
    // same sum as the chunked walk below). A GPU skips the shading where no lane of a warp is
    // in reach and reads an entry every lane of the warp shares (one cluster) as a broadcast;
    // the chunks exist for llvmpipe, whose if runs under a mask.
    for (uint i = begin; i < end; ++i) {
        vec4 positionRadius = clusterListSphere(first + i);
        if (lightDistance(positionRadius.xyz, s.position) < positionRadius.w) {
            ++evaluated;
            uint lightIndex = clusterListLight(first + i);
            color += shadeLocalLight(lightIndex, lightWithPositionRadius(lightIndex, positionRadius), s, V);
        }
    }
#else
    for (uint chunk = begin; chunk < end; chunk += REACH_CHUNK) {
        uint reached = 0u;  // bit k: entry chunk + k reaches the surface
        uint chunkEnd = min(end, chunk + REACH_CHUNK);
        for (uint i = chunk; i < chunkEnd; ++i) {
            vec4 positionRadius = clusterListSphere(first + i);
            if (lightDistance(positionRadius.xyz, s.position) < positionRadius.w)
                reached |= 1u << (i - chunk);
        }
        evaluated += uint(bitCount(reached));
        while (reached != 0u) {
            uint entry = first + chunk + uint(findLSB(reached));
            reached &= reached - 1u;
            uint lightIndex = clusterListLight(entry);
            color += shadeLocalLight(lightIndex, lightWithPositionRadius(lightIndex, clusterListSphere(entry)), s, V);
        }
    }
#endif
    return color;
}
