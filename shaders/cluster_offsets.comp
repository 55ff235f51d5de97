#version 450 core
// Clustered, step 3: exclusive prefix sum of the per-cluster light counts into list
// offsets, and the total after the last cluster. One workgroup: each thread sums a run of
// clusters, one thread scans the run totals, then each thread writes its run's offsets.
#include "lib/frame.glsl"
#include "lib/clusters.glsl"

layout(local_size_x = 1024) in;
layout(location = 0) uniform uint clusterCount;

shared uint runStart[1024];

void main()
{
    uint thread = gl_LocalInvocationID.x;
    uint perThread = (clusterCount + 1023u) / 1024u;
    uint begin = min(thread * perThread, clusterCount);
    uint end = min(begin + perThread, clusterCount);
    uint sum = 0u;
    for (uint i = begin; i < end; ++i)
        sum += clusterCounts[i];
    runStart[thread] = sum;
    barrier();
    if (thread == 0u) {
        uint running = 0u;
        for (uint k = 0u; k < 1024u; ++k) {
            uint value = runStart[k];
            runStart[k] = running;
            running += value;
        }
        clusterOffsets[clusterCount] = running;
    }
    barrier();
    uint running = runStart[thread];
    for (uint i = begin; i < end; ++i) {
        clusterOffsets[i] = running;
        running += clusterCounts[i];
    }
}
