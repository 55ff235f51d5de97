#version 450 core
// Tiled and clustered, once per frame of at most kMaskedListLights lights (render/culling/ClusterLists.h),
// in place of the pair sort: each cluster's mask (a bit per light, set by cluster_pairs.comp
// compiled with CLUSTER_MASKS) becomes its list, from the first entry the scan of the
// clusters' counts gave it, the lights in their order (bit order), each light's sphere beside
// it: the very lists the sort makes. An invocation per cluster, in rows of workgroups
// (render/programs/WorkgroupRows.h).
//
// A mask of more than 32 words has a summary, a bit per word that holds a light, and the walk
// takes only those words; a mask of up to 32 words (1,024 lights) has none, and the walk reads
// its words in turn (the summary's atomics in the pair passes cost more than it saved:
// docs/techniques.md). Either walk stops at the cluster's last light, which its count says.
//
// It clears what it read, each word that held a light and each summary word, so that the
// masks are all zero for the next frame without a clear of the whole buffer (60.8 MB at 16,384
// lights at 1280x720; most clusters' masks hold a few bits). Every bit set is in a word that
// the walk reaches before the cluster's last light (a summarised one in a marked word: the
// first bit set in a word marks it), so no bit survives the frame, whatever the capacity of
// the lists. (A summary bit that survived would only cost a read of a zero word.)
//
// Loop iterations: the summary's words, at most kMaskedListLights / 1,024, plus the words,
// at most kMaskedListLights / 32, plus half the cluster's lights, at most kMaskedListLights / 2:
// 8,720 for 16,384 lights, within render/programs/LightBatches.h's bound (ClusterLists.cpp checks).
#include "lib/bindings.glsl"
#include "lib/locations.glsl"
#include "lib/frame.glsl"
#include "lib/lights.glsl"
#include "lib/clusters.glsl"
#include "lib/listed_dispatch.glsl"

layout(local_size_x = 64) in;

layout(location = CLUSTER_MASK_WORDS_LOCATION) uniform uint maskWords;
layout(location = CLUSTER_MASK_CLUSTERS_LOCATION) uniform uint clusterCount;
layout(location = CLUSTER_MASK_CAPACITY_LOCATION) uniform uint pairCapacity;

layout(std430, binding = CLUSTER_LIST_FIRSTS_BUFFER_BINDING) readonly buffer ClusterListFirsts {
    uint clusterListFirst[];
};
layout(std430, binding = CLUSTER_LIST_LIGHTS_BUFFER_BINDING) writeonly buffer ClusterListLights {
    uint clusterListLight[];
};
layout(std430, binding = CLUSTER_LIST_SPHERES_BUFFER_BINDING) writeonly buffer ClusterListSpheres {
    vec4 clusterListSphere[];
};

layout(std430, binding = CLUSTER_LIST_COUNTS_BUFFER_BINDING) readonly buffer ClusterListCounts {
    uint clusterListCount[];
};

// Writes entry `entry` of the lists, where the storage holds it: past the storage the frame
// was planned with, the CPU redoes the frame (pairsNeeded, from the scan, counted every pair).
void listLight(uint entry, uint lightIndex)
{
    if (entry < pairCapacity) {
        clusterListLight[entry] = lightIndex;
        clusterListSphere[entry] = lights[lightIndex].positionRadius;
    }
}

void main()
{
    uint cluster = listedGroup() * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (cluster >= clusterCount)
        return;
    uint entry = clusterListFirst[cluster];
    uint end = entry + clusterListCount[cluster];
    bool summarised = listMaskSummarised(maskWords);
    uint summaryWords = clusterMaskSummaryWords(maskWords);
    for (uint s = 0u; s < summaryWords && entry < end; ++s) {
        uint marked = ~0u;
        if (summarised) {
            marked = clusterMaskSummaries[cluster * summaryWords + s];
            clusterMaskSummaries[cluster * summaryWords + s] = 0u;
        } else if (maskWords < 32u) {
            marked = (1u << maskWords) - 1u;
        }
        while (marked != 0u && entry < end) {
            uint word = s * 32u + uint(findLSB(marked));
            marked &= marked - 1u;
            uint bits = clusterLightMasks[cluster * maskWords + word];
            if (bits == 0u)
                continue;
            clusterLightMasks[cluster * maskWords + word] = 0u;
            // Two lights an iteration (the second where the word holds one more), so that a
            // cluster that every light reaches stays within the loop bound.
            while (bits != 0u) {
                listLight(entry++, word * 32u + uint(findLSB(bits)));
                bits &= bits - 1u;
                if (bits != 0u) {
                    listLight(entry++, word * 32u + uint(findLSB(bits)));
                    bits &= bits - 1u;
                }
            }
        }
    }
}
