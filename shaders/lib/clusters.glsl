// The cluster grid of the clustered technique (render/ClusteredTechnique.h): screen tiles of
// CLUSTER_TILE_SIZE pixels times CLUSTER_SLICES depth slices spaced exponentially between
// the nearest and the farthest visible surface of the frame (found by
// cluster_depth_range.comp), so that no slice is spent on empty depth before or after the
// scene.
//
// Per cluster: an occupancy flag (does any pixel's surface fall in it), the number of lights
// that reach it, and the offset of its list in one global index buffer.
layout(std430, binding = 2) buffer ClusterOccupancy {
    uint clusterOccupied[];
};
layout(std430, binding = 3) buffer ClusterCounts {
    uint clusterCounts[];
};
layout(std430, binding = 4) buffer ClusterOffsets {
    uint clusterOffsets[];  // one more entry than clusters: the total
};
layout(std430, binding = 5) buffer ClusterLightIndices {
    uint clusterLightIndices[];
};
layout(std430, binding = 7) buffer ClusterDepthRange {
    uint sceneDepthBits[2];  // nearest and farthest surface depth, as float bits
};

// The depth range the slices span, widened a little so that rounding cannot put the
// nearest or farthest surface outside it.
float slicedNear()
{
    return max(uintBitsToFloat(sceneDepthBits[0]) * 0.99, frame.projection.z * 0.5);
}

float slicedFar()
{
    return max(uintBitsToFloat(sceneDepthBits[1]) * 1.01, slicedNear() * 1.01);
}

uvec3 clusterGridSize()
{
    return uvec3((uvec2(frame.viewport.xy) + uint(CLUSTER_TILE_SIZE - 1)) / uint(CLUSTER_TILE_SIZE),
                 uint(CLUSTER_SLICES));
}

uint clusterIndex(uvec3 cluster)
{
    uvec3 grid = clusterGridSize();
    return (cluster.z * grid.y + cluster.y) * grid.x + cluster.x;
}

// The slice holding view depth z; depths outside [near, far] fall in the end slices.
uint sliceOfDepth(float z)
{
    float near = slicedNear();
    float far = slicedFar();
    float slice = floor(log(max(z, near) / near) / log(far / near) * float(CLUSTER_SLICES));
    return uint(clamp(slice, 0.0, float(CLUSTER_SLICES - 1)));
}

// The view depth where slice k begins.
float sliceStart(uint k)
{
    float near = slicedNear();
    float far = slicedFar();
    return near * pow(far / near, float(k) / float(CLUSTER_SLICES));
}

uvec3 clusterOfPixel(vec2 pixel, float depth)
{
    return uvec3(uvec2(pixel) / uint(CLUSTER_TILE_SIZE), sliceOfDepth(depth));
}

// The view-space box around a cluster (the camera looks down -Z). It is grown by a small
// margin: a pixel is assigned its cluster with floating-point logs, so a surface on a slice
// boundary must be inside the boxes of both neighbours, or a light could miss it.
void clusterBox(uvec3 cluster, out vec3 lo, out vec3 hi)
{
    vec2 pixelLo = vec2(cluster.xy * uint(CLUSTER_TILE_SIZE));
    vec2 pixelHi = min(pixelLo + float(CLUSTER_TILE_SIZE), frame.viewport.xy);
    vec2 ndcLo = pixelLo * frame.viewport.zw * 2.0 - 1.0;
    vec2 ndcHi = pixelHi * frame.viewport.zw * 2.0 - 1.0;
    float zNear = sliceStart(cluster.z);
    float zFar = cluster.z + 1u == uint(CLUSTER_SLICES) ? slicedFar() : sliceStart(cluster.z + 1u);
    if (cluster.z == 0u)
        zNear = 0.0;  // everything in front of the first boundary, the eye included
    zNear *= 0.999;
    zFar *= 1.001;
    lo = vec3(1e30);
    hi = vec3(-1e30);
    for (int corner = 0; corner < 8; ++corner) {
        vec2 ndc = vec2((corner & 1) != 0 ? ndcHi.x : ndcLo.x, (corner & 2) != 0 ? ndcHi.y : ndcLo.y);
        float z = (corner & 4) != 0 ? zFar : zNear;
        vec3 p = vec3(ndc * frame.projection.xy * z, -z);
        lo = min(lo, p);
        hi = max(hi, p);
    }
}
