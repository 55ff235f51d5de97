#version 450 core
// Clustered, steps 2 and 4: one thread per light visits the occupied clusters its bounding
// sphere's screen rectangle and depth range cover, and keeps those whose box the sphere (and
// a spot's cone) reaches. With FILL_LISTS undefined it counts per cluster; defined, it writes
// the light into the cluster's list at the offset the prefix sum gave (clusterCounts then
// serves as each list's cursor, cleared in between).
#include "lib/falloff.glsl"
#include "lib/frame.glsl"
#include "lib/lights.glsl"
#include "lib/clusters.glsl"
#include "lib/culling.glsl"

layout(local_size_x = 64) in;

void main()
{
    uint lightIndex = gl_GlobalInvocationID.x;
    if (lightIndex >= frame.counts.x)
        return;
    GpuLight light = lights[lightIndex];
    float radius = light.positionRadius.w;
    if (radius <= 0.0)
        return;
    uvec3 grid = clusterGridSize();
    float near = frame.projection.z;
    float far = slicedFar();
    bool unbounded = radius >= UNBOUNDED_RADIUS;
    vec3 centre = (frame.view * vec4(light.positionRadius.xyz, 1.0)).xyz;
    vec3 axis = mat3(frame.view) * light.spotAxisCosCutoff.xyz;
    float depthMin = -centre.z - radius;
    float depthMax = -centre.z + radius;
    if (!unbounded && (depthMax < near || depthMin > far))
        return;

    uvec3 first = uvec3(0u);
    uvec3 last = grid - 1u;
    if (!unbounded) {
        first.z = sliceOfDepth(depthMin);
        last.z = sliceOfDepth(depthMax);
        // A sphere wholly in front of the near plane projects inside the projection of its
        // bounding box's corners; one reaching the eye plane may cover any tile.
        if (depthMin > near) {
            vec2 ndcLo = vec2(1e30);
            vec2 ndcHi = vec2(-1e30);
            for (int corner = 0; corner < 8; ++corner) {
                vec3 p = centre + radius * vec3((corner & 1) != 0 ? 1.0 : -1.0, (corner & 2) != 0 ? 1.0 : -1.0,
                                                (corner & 4) != 0 ? 1.0 : -1.0);
                vec2 ndc = p.xy / (-p.z * frame.projection.xy);
                ndcLo = min(ndcLo, ndc);
                ndcHi = max(ndcHi, ndc);
            }
            if (any(greaterThan(ndcLo, vec2(1.0))) || any(lessThan(ndcHi, vec2(-1.0))))
                return;
            vec2 pixelLo = (clamp(ndcLo, -1.0, 1.0) * 0.5 + 0.5) * frame.viewport.xy;
            vec2 pixelHi = (clamp(ndcHi, -1.0, 1.0) * 0.5 + 0.5) * frame.viewport.xy;
            first.xy = min(uvec2(pixelLo) / uint(CLUSTER_TILE_SIZE), grid.xy - 1u);
            last.xy = min(uvec2(pixelHi) / uint(CLUSTER_TILE_SIZE), grid.xy - 1u);
        }
    }

    for (uint z = first.z; z <= last.z; ++z)
        for (uint y = first.y; y <= last.y; ++y)
            for (uint x = first.x; x <= last.x; ++x) {
                uvec3 cluster = uvec3(x, y, z);
                uint index = clusterIndex(cluster);
                if (clusterOccupied[index] == 0u)
                    continue;
                if (!unbounded) {
                    vec3 lo;
                    vec3 hi;
                    clusterBox(cluster, lo, hi);
                    if (!sphereTouchesBox(centre, radius, lo, hi))
                        continue;
                    if (!coneTouchesSphere(centre, axis, light.spotAxisCosCutoff.w, 0.5 * (lo + hi),
                                           0.5 * length(hi - lo)))
                        continue;
                }
#ifdef FILL_LISTS
                uint slot = atomicAdd(clusterCounts[index], 1u);
                clusterLightIndices[clusterOffsets[index] + slot] = lightIndex;
#else
                atomicAdd(clusterCounts[index], 1u);
#endif
            }
}
