#version 450 core
// Clustered, once per frame (render/culling/ClusterLists.h): the (cluster, light) pairs, in two runs of
// two programs each. The counting run counts each light's pairs, which a scan turns into each
// light's first slot; the writing run writes them there, the cluster as the sort key and the
// light as the value, and counts each cluster's. Each program is compiled for each run
// (EMIT_PAIRS 0 and 1) from one source, so that both runs make the same decisions to the last
// bit and neither carries the other's code: llvmpipe runs every line of an invocation's
// program under a mask, whichever branch its lanes take (courtyard, a million lights: the
// writing run 32 -> 24 ms as a program of its own). The lights are shared out two ways:
// - the narrow program, an invocation per light, walks the tiles its sphere covers on screen,
//   when they are at most CLUSTER_PAIR_NARROW_TILES; the counting run lists the others as wide
//   lights. Most lights of a large scene are small: an invocation each, not a workgroup (at a
//   million lights a workgroup per light cost 0.6 us of llvmpipe's dispatch alone). The
//   counting run also lists the lights it found pairs for, and keeps what it found for those
//   of at most 2 x 2 tiles (most lights of a large scene): the tiles and each one's slices, 64
//   bits. The writing run is an invocation per listed light (an indirect dispatch), and only
//   writes a kept light's pairs instead of culling it again: most lights of a large scene reach
//   no surface, and cost the writing run nothing;
// - the wide program, a workgroup per wide light and band of tile rows (an indirect dispatch
//   over the list), its LIGHT_TILE_LANES invocations sharing out the tiles
//   (lib/light_tiles.glsl): 8 lanes in lock step each walking a light of hundreds of tiles
//   would wait for the largest.
//
// A light whose screen rectangle covers at least globalLightTiles tiles (or that is unbounded)
// is a candidate for the global list (lib/cluster_lists.glsl), which every pixel walks: the
// counting run lists it in globalLightCandidate (up to GLOBAL_LIGHT_CAPACITY; all are counted)
// and among the wide lights, marked. Where every candidate fits (globalLightCount()), the wide
// program gives the marked ones no pair; where they do not, they are wide lights as any other.
// All or none, so that which lights are global does not depend on the order the invocations
// ran in, and the image stays the same from run to run. A frame has a global list only where
// the frame before had candidates (globalListPlanned), so that the lighting of a scene without
// them does not pay for walking an empty list; the candidates are counted either way.
//
// A light's pairs may be written in any order (a wide light's slots are handed out by an
// atomic) and the lights with pairs listed in any order (by an atomic too), since no two of a
// light's pairs share a cluster and its slots follow from its index: sorted by cluster, each
// cluster's lights follow the lights' order, whatever order the invocations ran in.
//
// With CLUSTER_MASKS (a frame of at most ClusterLists.h's kMaskedListLights lights) the pairs
// are bits instead: each sets the light's bit in its cluster's mask (and, where the masks are
// summarised, the mask word's bit in the cluster's summary) and counts the cluster's pair, and cluster_mask_lists.comp turns the
// masks into the same lists as the sort would, in the lights' order. Then no light needs a
// slot: the narrow lights set their bits in the counting run, which has no writing run after
// it, and the wide lights in the wide program's writing run.
//
// Loop iterations per invocation: CLUSTER_PAIR_NARROW_TILES tiles, or at most 1,024 (the bands
// of lib/light_tiles.glsl), each with at most CLUSTER_SLICES slices (lib/cluster_culling.glsl):
// about 9,200 at most, within render/programs/LightBatches.h's bound.
#include "lib/bindings.glsl"
#include "lib/locations.glsl"
#include "lib/falloff.glsl"
#include "lib/frame.glsl"
#include "lib/lights.glsl"
#include "lib/clusters.glsl"
#include "lib/culling.glsl"
#include "lib/cluster_culling.glsl"
#include "lib/cluster_list_status.glsl"
#include "lib/listed_dispatch.glsl"
#ifdef WIDE_LIGHTS
#include "lib/light_tiles.glsl"
#else
layout(local_size_x = 64) in;
#endif

const uint emitPairs = EMIT_PAIRS;  // 0 in the counting run, 1 in the writing run
#ifndef WIDE_LIGHTS
layout(location = CLUSTER_PAIR_LIGHT_COUNT_LOCATION) uniform uint lightCount;
#endif
layout(std430, binding = LIGHT_PAIR_OFFSETS_BUFFER_BINDING) buffer LightPairOffsets {
    uint lightPairOffset[];  // counting: each light's pairs; writing: its first slot
};
layout(std430, binding = WIDE_LIGHTS_BUFFER_BINDING) buffer WideLights {
    uint wideLight[];  // the lights for the wide program, GLOBAL_CANDIDATE_BIT marking candidates
};
layout(std430, binding = PAIRED_LIGHTS_BUFFER_BINDING) buffer PairedLights {
    uint pairedLight[];  // the narrow lights with pairs, for the writing run
};
// Marks a wide light that is a candidate for the global list (light indices are below 2^24).
const uint GLOBAL_CANDIDATE_BIT = 0x80000000u;
#if !defined(WIDE_LIGHTS) && !EMIT_PAIRS
layout(location = CLUSTER_PAIR_GLOBAL_TILES_LOCATION) uniform uint globalLightTiles;
layout(location = CLUSTER_PAIR_GLOBAL_PLANNED_LOCATION) uniform uint globalListPlanned;  // this frame has one
layout(std430, binding = GLOBAL_LIGHT_CANDIDATES_BUFFER_BINDING) writeonly buffer GlobalLightCandidates {
    uint globalLightCandidate[];  // in the order the invocations ran: global_light_order.comp sorts them
};
#endif
layout(location = CLUSTER_PAIR_CAPACITY_LOCATION) uniform uint pairCapacity;
layout(std430, binding = LIGHT_PAIR_CURSORS_BUFFER_BINDING) buffer LightPairCursors {
    uint lightPairCursor[];  // a wide light's slots handed out so far
};
layout(std430, binding = PAIR_KEYS_IN_BUFFER_BINDING) writeonly buffer PairKeys {
    uint pairKey[];  // the cluster
};
layout(std430, binding = CLUSTER_LIST_LIGHTS_BUFFER_BINDING) writeonly buffer PairLights {
    uint pairLight[];  // the light
};
layout(std430, binding = CLUSTER_LIST_COUNTS_BUFFER_BINDING) buffer ClusterListCounts {
    uint clusterPairCount[];  // each cluster's pairs (its list's length)
};
#ifdef CLUSTER_MASKS
// The words of each cluster's mask: a bit per light (lib/clusters.glsl's masks, over every
// light of the frame instead of a batch).
layout(location = CLUSTER_MASK_WORDS_LOCATION) uniform uint maskWords;

// Sets the light's bit in the masks of the clusters `slices` (bit k: slice k) of `tile`.
void setTileBits(uint slices, uint tile, uint lightIndex)
{
    bool summarised = listMaskSummarised(maskWords);
    while (slices != 0u) {
        uint cluster = tile * uint(CLUSTER_SLICES) + uint(findLSB(slices));
        slices &= slices - 1u;
        setClusterMaskBit(cluster, maskWords, lightIndex / 32u, 1u << (lightIndex % 32u), summarised);
        atomicAdd(clusterPairCount[cluster], 1u);
    }
}
#endif
#ifndef WIDE_LIGHTS
// Per light, what the counting run found, for the writing run: x the rectangle of at most
// 2 x 2 tiles (first tile's x in bits 0-14 and y in 15-29, one more column in bit 30, one more
// row in bit 31), y each of its tiles' slices (8 bits a tile, row by row); x = NO_RECORD where
// the writing run must cull the light itself. Written for every light with pairs, so nothing
// is left from an earlier frame.
layout(std430, binding = LIGHT_TILE_RECORDS_BUFFER_BINDING) buffer LightTileRecords {
    uvec2 lightTileRecord[];
};
const uint NO_RECORD = 0xffffffffu;
const uint RECORD_COORDINATE_LIMIT = 0x7fffu;  // tiles across or down that a record can name

// Tile k (row by row) of a rectangle of `size` tiles from `first`.
uint tileOfRect(uvec2 first, uvec2 size, uint k, uvec2 grid)
{
    return (first.y + k / size.x) * grid.x + first.x + k % size.x;
}
#endif

// The tiles the light's sphere covers, first to last; false when it reaches none (wholly
// before the near plane, or off screen). Both runs call it on the same light with the same
// inputs: the same answer.
bool lightTileRect(ViewLight light, uvec2 grid, out uvec2 first, out uvec2 last)
{
    first = uvec2(0u);
    last = grid - 1u;
    return light.unbounded || (-light.centre.z + light.radius >= frame.projection.z &&
                               sphereTileRect(light.centre, light.radius, uint(CLUSTER_TILE_SIZE), grid, first, last));
}

void emitPair(uint slot, uint cluster, uint lightIndex)
{
    // Past the storage the frame was planned with: the scan has counted every pair in
    // pairsNeeded, so the CPU sees the overflow and redoes the frame.
    if (slot < pairCapacity) {
        pairKey[slot] = cluster;
        pairLight[slot] = lightIndex;
        atomicAdd(clusterPairCount[cluster], 1u);
    }
}

// Writes the light's pairs with the clusters `slices` (bit k: slice k) of `tile` from `slot` on.
void emitTilePairs(uint slices, uint tile, uint lightIndex, uint slot)
{
    while (slices != 0u) {
        uint cluster = tile * uint(CLUSTER_SLICES) + uint(findLSB(slices));
        slices &= slices - 1u;
        emitPair(slot++, cluster, lightIndex);
    }
}

// The pairs of `tile` for the light: counted, or written from `slot` on (a narrow light's
// next slot; a wide light's come from its cursor). Returns the count.
uint tilePairs(ViewLight light, uint lightIndex, uint tile, uint slot)
{
    uint slices = lightSlicesOfTile(light, tile);
    uint pairs = uint(bitCount(slices));
    if (emitPairs == 0u || pairs == 0u)
        return pairs;
#ifdef CLUSTER_MASKS
    setTileBits(slices, tile, lightIndex);
    return pairs;
#endif
#ifdef WIDE_LIGHTS
    // A wide light's invocations share its slots: one atomic per tile, not per pair.
    slot = lightPairOffset[lightIndex] + atomicAdd(lightPairCursor[lightIndex], pairs);
#endif
    emitTilePairs(slices, tile, lightIndex, slot);
    return pairs;
}

#ifdef WIDE_LIGHTS
void main()
{
    uint wide = listedGroup();
    if (wide >= wideLights)
        return;
    uvec2 grid = clusterTileGrid();
    uint entry = wideLight[wide];
    // A candidate for the global list has no pairs where the list holds every candidate.
    if ((entry & GLOBAL_CANDIDATE_BIT) != 0u && globalLightCount() != 0u)
        return;
    uint lightIndex = entry & ~GLOBAL_CANDIDATE_BIT;
    ViewLight light = viewLight(lights[lightIndex]);
    LightTileRun run;
    if (!lightTileRun(light.centre, light.radius, light.unbounded, uint(CLUSTER_TILE_SIZE), grid, run))
        return;
    uint pairs = 0u;
    for (uint i = gl_LocalInvocationID.x; i < run.tiles; i += uint(LIGHT_TILE_LANES))
        pairs += tilePairs(light, lightIndex, tileOfRun(run, i, grid.x), 0u);
    if (emitPairs == 0u && pairs != 0u)
        atomicAdd(lightPairOffset[lightIndex], pairs);
}
#elif EMIT_PAIRS
void main()
{
    uint paired = listedGroup() * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (paired >= pairedLights)
        return;
    uint lightIndex = pairedLight[paired];
    uvec2 grid = clusterTileGrid();
    uint slot = lightPairOffset[lightIndex];
    uvec2 record = lightTileRecord[lightIndex];
    if (record.x != NO_RECORD) {
        uvec2 first = uvec2(record.x & RECORD_COORDINATE_LIMIT, (record.x >> 15u) & RECORD_COORDINATE_LIMIT);
        uvec2 size = uvec2(1u + ((record.x >> 30u) & 1u), 1u + (record.x >> 31u));
        for (uint k = 0u; k < size.x * size.y; ++k) {
            uint slices = (record.y >> (8u * k)) & 0xffu;
            emitTilePairs(slices, tileOfRect(first, size, k, grid), lightIndex, slot);
            slot += uint(bitCount(slices));
        }
        return;
    }
    ViewLight light = viewLight(lights[lightIndex]);
    uvec2 first;
    uvec2 last;
    lightTileRect(light, grid, first, last);  // true: the counting run found pairs
    uvec2 size = last - first + 1u;
    for (uint k = 0u; k < size.x * size.y; ++k)
        slot += tilePairs(light, lightIndex, tileOfRect(first, size, k, grid), slot);
}
#else
void main()
{
    // Lights in rows of workgroups (render/programs/WorkgroupRows.h).
    uint lightIndex = listedGroup() * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (lightIndex >= lightCount)
        return;
    uvec2 grid = clusterTileGrid();
    ViewLight light = viewLight(lights[lightIndex]);
    uvec2 first;
    uvec2 last;
    if (light.radius <= 0.0 || !lightTileRect(light, grid, first, last))
        return;
    uvec2 size = last - first + 1u;
    // Counted whether or not this frame has a global list: the next frame's plan.
    bool global = light.unbounded || size.x * size.y >= globalLightTiles;
    uint candidate = global ? atomicAdd(globalLightCandidates, 1u) : 0u;
    bool listed = global && globalListPlanned != 0u;
    if (listed || light.unbounded || size.x * size.y > uint(CLUSTER_PAIR_NARROW_TILES)) {
        uint entry = lightIndex;
        if (listed) {
            if (candidate < uint(GLOBAL_LIGHT_CAPACITY))
                globalLightCandidate[candidate] = lightIndex;
            entry |= GLOBAL_CANDIDATE_BIT;
        }
        uint wide = atomicAdd(wideLights, 1u);
        wideLight[wide] = entry;
        uvec2 growth = listedDispatchGrowth(wide, 1u);
        if (growth.x != 0u)
            atomicAdd(wideLightGroups[0], 1u);
        if (growth.y != 0u)
            atomicAdd(wideLightGroups[2], 1u);
        return;
    }
#ifdef CLUSTER_MASKS
    for (uint k = 0u; k < size.x * size.y; ++k) {
        uint tile = tileOfRect(first, size, k, grid);
        setTileBits(lightSlicesOfTile(light, tile), tile, lightIndex);
    }
#else
    // One walk over the tiles for every narrow light, the slices of the first four kept as
    // they come (the record's, when the light covers at most 2 x 2 tiles): one copy of the
    // tile test in the program, not one for the recorded lights and one for the others.
    uint masks = 0u;
    uint pairs = 0u;
    for (uint k = 0u; k < size.x * size.y; ++k) {
        uint slices = lightSlicesOfTile(light, tileOfRect(first, size, k, grid));
        masks |= slices << (8u * (k & 3u));
        pairs += uint(bitCount(slices));
    }
    if (pairs == 0u)
        return;
    lightPairOffset[lightIndex] = pairs;
    bool recorded = CLUSTER_SLICES <= 8 && size.x <= 2u && size.y <= 2u && last.x < RECORD_COORDINATE_LIMIT &&
                    last.y < RECORD_COORDINATE_LIMIT;
    lightTileRecord[lightIndex] =
        recorded ? uvec2(first.x | first.y << 15u | (size.x - 1u) << 30u | (size.y - 1u) << 31u, masks)
                 : uvec2(NO_RECORD, 0u);
    uint paired = atomicAdd(pairedLights, 1u);
    pairedLight[paired] = lightIndex;
    uvec2 growth = listedDispatchGrowth(paired, gl_WorkGroupSize.x);
    if (growth.x != 0u)
        atomicAdd(pairedLightGroups[0], 1u);
    if (growth.y != 0u)
        atomicAdd(pairedLightGroups[2], 1u);
#endif
}
#endif
