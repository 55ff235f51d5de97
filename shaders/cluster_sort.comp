#version 450 core
// Clustered, step 5: sort each cluster's list by light index. The fill order comes from
// atomics and changes from run to run; sorted, every pixel adds its lights in the order
// forward does, so the image is the same every time (and equal to forward's bit for bit
// where the shader compiles alike). Lists are short: insertion sort.
#include "lib/frame.glsl"
#include "lib/clusters.glsl"

layout(local_size_x = 64) in;
layout(location = 0) uniform uint clusterCount;

void main()
{
    uint cluster = gl_GlobalInvocationID.x;
    if (cluster >= clusterCount)
        return;
    uint begin = clusterOffsets[cluster];
    uint end = begin + clusterCounts[cluster];
    for (uint i = begin + 1u; i < end; ++i) {
        uint value = clusterLightIndices[i];
        uint j = i;
        while (j > begin && clusterLightIndices[j - 1u] > value) {
            clusterLightIndices[j] = clusterLightIndices[j - 1u];
            --j;
        }
        clusterLightIndices[j] = value;
    }
}
