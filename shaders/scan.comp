#version 450 core
// An exclusive prefix sum over a storage buffer of uints, in place (render/culling/GpuScan.h): the
// step of one level of the scan that SCAN_STEP names, the levels run from the CPU.
//   0 (reduce): block i's sum (SCAN_BLOCK elements from i · SCAN_BLOCK) into partials[i];
//   1 (top): one invocation scans the whole (at most SCAN_BLOCK elements) and writes the
//      total to totals[totalIndex] when totalIndex is not ~0;
//   2 (spread): block i, scanned from partials[i] (its exclusive prefix, scanned a level up).
// One invocation per block walking it in order rather than a workgroup meeting at barriers:
// llvmpipe runs barriers by switching between invocations, which costs more than the walk, and
// the walk keeps the sum's order fixed. Loop iterations: SCAN_BLOCK per invocation.
#include "lib/bindings.glsl"
#include "lib/locations.glsl"

layout(local_size_x = 64) in;
layout(location = SCAN_COUNT_LOCATION) uniform uint count;  // elements of data
layout(location = SCAN_TOTAL_INDEX_LOCATION) uniform uint totalIndex;

layout(std430, binding = SCAN_DATA_BUFFER_BINDING) buffer ScanData {
    uint data[];
};
layout(std430, binding = SCAN_PARTIALS_BUFFER_BINDING) buffer ScanPartials {
    uint partials[];
};
#if SCAN_STEP == 1
layout(std430, binding = CLUSTER_LIST_STATUS_BUFFER_BINDING) buffer ScanTotals {
    uint totals[];
};
#endif

void main()
{
#if SCAN_STEP == 1
    if (gl_GlobalInvocationID.x != 0u)
        return;
    uint running = 0u;
    for (uint i = 0u; i < count; ++i) {
        uint value = data[i];
        data[i] = running;
        running += value;
    }
    if (totalIndex != ~0u)
        totals[totalIndex] = running;
#else
    uint block = gl_GlobalInvocationID.x;
    uint first = block * uint(SCAN_BLOCK);
    if (first >= count)
        return;
    uint end = min(first + uint(SCAN_BLOCK), count);
#if SCAN_STEP == 0
    uint sum = 0u;
    for (uint i = first; i < end; ++i)
        sum += data[i];
    partials[block] = sum;
#else
    uint running = partials[block];
    for (uint i = first; i < end; ++i) {
        uint value = data[i];
        data[i] = running;
        running += value;
    }
#endif
#endif
}
