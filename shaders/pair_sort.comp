#version 450 core
// One digit of the (cluster, light) pairs' radix sort by cluster (render/culling/ClusterLists.h),
// stable, least significant digit first: with PAIR_SORT_SCATTER it moves each pair to its
// place, without it counts each chunk's pairs per digit value. Between the two, the counts
// (laid out digit value by digit value, chunk by chunk) are scanned (scan.comp), which gives
// every (digit value, chunk) the place of its first pair.
//
// One invocation per chunk of PAIR_SORT_CHUNK consecutive pairs, walking them in order: the
// pairs of one digit value keep their order, which makes the sort stable, so each cluster's
// lights stay in the order the lights were written in (cluster_pairs.comp) and the image does
// not depend on the order in which invocations ran. Loop iterations: PAIR_SORT_CHUNK plus
// 2 · PAIR_SORT_RADIX.
//
// With PAIR_SORT_GATHER too (the last digit), each pair's light sphere goes beside it: the
// lighting's per-pixel reach test then reads the lists' spheres in order instead of the
// lights' positions scattered over the light buffer (lib/cluster_lists.glsl).
#include "lib/bindings.glsl"
#include "lib/locations.glsl"
#include "lib/cluster_list_status.glsl"
#ifdef PAIR_SORT_GATHER
#include "lib/lights.glsl"
layout(std430, binding = CLUSTER_LIST_SPHERES_BUFFER_BINDING) writeonly buffer PairSpheresOut {
    vec4 sphereOut[];
};
#endif

layout(local_size_x = 64) in;
layout(location = PAIR_SORT_SHIFT_LOCATION) uniform uint shift;
layout(location = PAIR_SORT_CHUNKS_LOCATION) uniform uint chunks;
layout(location = PAIR_SORT_CAPACITY_LOCATION) uniform uint pairCapacity;

layout(std430, binding = SCAN_DATA_BUFFER_BINDING) buffer Histogram {
    uint histogram[];  // [digit value · chunks + chunk]
};
layout(std430, binding = PAIR_KEYS_IN_BUFFER_BINDING) readonly buffer PairKeysIn {
    uint keyIn[];
};
#ifdef PAIR_SORT_SCATTER
layout(std430, binding = CLUSTER_LIST_LIGHTS_BUFFER_BINDING) readonly buffer PairLightsIn {
    uint lightIn[];
};
layout(std430, binding = PAIR_KEYS_OUT_BUFFER_BINDING) writeonly buffer PairKeysOut {
    uint keyOut[];
};
layout(std430, binding = PAIR_LIGHTS_OUT_BUFFER_BINDING) writeonly buffer PairLightsOut {
    uint lightOut[];
};
#endif

void main()
{
    uint chunk = gl_GlobalInvocationID.x;
    if (chunk >= chunks)
        return;
    // The pairs written: past the capacity none were (the frame is then redone).
    uint pairs = min(pairsNeeded, pairCapacity);
    uint first = chunk * uint(PAIR_SORT_CHUNK);
    uint end = min(first + uint(PAIR_SORT_CHUNK), pairs);
    uint mask = uint(PAIR_SORT_RADIX) - 1u;
    uint place[PAIR_SORT_RADIX];
    for (uint d = 0u; d < uint(PAIR_SORT_RADIX); ++d)
#ifdef PAIR_SORT_SCATTER
        place[d] = histogram[d * chunks + chunk];
#else
        place[d] = 0u;
#endif
    for (uint i = first; i < end; ++i) {
        uint key = keyIn[i];
        uint d = (key >> shift) & mask;
#ifdef PAIR_SORT_SCATTER
        uint to = place[d]++;
        keyOut[to] = key;
        uint lightIndex = lightIn[i];
        lightOut[to] = lightIndex;
#ifdef PAIR_SORT_GATHER
        sphereOut[to] = lights[lightIndex].positionRadius;
#endif
#else
        ++place[d];
#endif
    }
#ifndef PAIR_SORT_SCATTER
    for (uint d = 0u; d < uint(PAIR_SORT_RADIX); ++d)
        histogram[d * chunks + chunk] = place[d];
#endif
}
