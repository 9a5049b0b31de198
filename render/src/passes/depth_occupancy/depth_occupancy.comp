#version 460
#extension GL_GOOGLE_include_directive : require
#include "depth_occupancy_bindings.h"
// Per screen tile, which depth slices hold a pixel (a 64-bit mask per tile) and, per quarter
// of the tile, the view-space box around those pixels. Light assignment skips empty clusters
// and tests lights against the boxes of the surfaces actually there, so light lists shrink to
// the depths present and each entry says which quarters its light reaches
// (light_list_entry.h).
#include "common/clusters.glsl"

// One invocation per tile quarter walks its pixels in order and keeps the box of the current
// run of pixels in one slice in registers, writing it out when the slice changes: no shared
// atomics (lavapipe runs a lane's atomics one at a time, and one per pixel and axis made this
// pass a fifth of the games' frames) and one barrier, before the quarters of a tile merge.
// Invocations x: the tile's 4 quarters; y: 8 tiles (linear tile index).
layout(local_size_x = 4, local_size_y = 8) in;
const uint kTilesPerGroup = 8u;

layout(binding = OCCUPANCY_BINDING_DEPTH) uniform sampler2D depthBuffer;
layout(std430, binding = OCCUPANCY_BINDING_TILE_MASKS) writeonly buffer Occupancy {
    uvec2 tileMasks[];
};
// Per cluster, min xyz and max xyz of its pixels in view space, then per cluster and quarter
// the same, kEmptyQuarterBound-empty for a quarter without pixels (light_list_entry.h;
// unwritten where unoccupied). Coherent: each tile's quarters read each other's boxes after
// the barrier.
layout(std430, binding = OCCUPANCY_BINDING_CLUSTER_BOUNDS) coherent buffer ClusterBounds {
    float clusterBounds[];
};
// From depth_range.comp: [0] min, [1] max view depth (ordered bits); this pass writes the
// slicing it derived into [2] sliceNear and [3] logRatio (float bits) for the CPU and the
// lighting pass, so all three use bit-identical values.
layout(std430, binding = OCCUPANCY_BINDING_DEPTH_RANGE) buffer DepthRange { uint range[]; };

layout(push_constant) uniform Push {
    ClusterGridParams grid;
    uvec2 size;
    vec2 projectionScale;  // projection[0][0], projection[1][1]
} push;

shared uvec2 quarterMasks[kTilesPerGroup * 4u];

const uint kNoSlice = 0xffffffffu;

bool hasSlice(uvec2 mask, uint slice) {
    return ((slice < 32u ? mask.x >> slice : mask.y >> (slice - 32u)) & 1u) != 0u;
}

uvec2 sliceBit(uint slice) {
    return slice < 32u ? uvec2(1u << slice, 0u) : uvec2(0u, 1u << (slice - 32u));
}

// Where quarter `quarter` of cluster `cluster` keeps its box.
uint quarterBox(uint clusterCount, uint cluster, uint quarter) {
    return clusterCount * CLUSTER_BOX_FLOATS + cluster * CLUSTER_QUARTER_BOXES_FLOATS +
           quarter * 6u;
}

void storeBox(uint at, vec3 lo, vec3 hi) {
    for (uint c = 0u; c < 3u; ++c) {
        clusterBounds[at + c] = lo[c];
        clusterBounds[at + 3u + c] = hi[c];
    }
}

// Adds the run's box [lo, hi] in slice `slice` (kNoSlice: no run yet) to that slice's box of
// this quarter, which the slice's first run stores; `mask` gains the slice.
void flushRun(uint at, uint slice, vec3 lo, vec3 hi, inout uvec2 mask) {
    if (slice == kNoSlice) return;
    if (hasSlice(mask, slice)) {
        for (uint c = 0u; c < 3u; ++c) {
            lo[c] = min(lo[c], clusterBounds[at + c]);
            hi[c] = max(hi[c], clusterBounds[at + 3u + c]);
        }
    }
    storeBox(at, lo, hi);
    mask |= sliceBit(slice);
}

void main() {
    // Slices span the depths present: from the nearest to the farthest geometry.
    float minDepth = range[0] == 0xffffffffu ? push.grid.projectionNear : fromOrderedBits(range[0]);
    float maxDepth = range[1] == 0u ? minDepth : fromOrderedBits(range[1]);
    float sliceNear = max(minDepth, push.grid.projectionNear);
    float logRatio = log(max(maxDepth, sliceNear * 1.01) / sliceNear) / float(push.grid.slices);
    if (gl_WorkGroupID.x == 0u && gl_LocalInvocationIndex == 0u) {
        range[2] = floatBitsToUint(sliceNear);
        range[3] = floatBitsToUint(logRatio);
    }
    uint tileCount = push.grid.tilesX * push.grid.tilesY;
    uint clusterCount = tileCount * push.grid.slices;
    uint quarter = gl_LocalInvocationID.x;
    uint tileIndex = gl_WorkGroupID.x * kTilesPerGroup + gl_LocalInvocationID.y;
    uvec2 tile = uvec2(tileIndex % push.grid.tilesX, tileIndex / push.grid.tilesX);
    // quarterOfPixel's split: the first half of a tile's side is its first (size + 1) / 2
    // pixels.
    uint tileSize = push.grid.tileSize;
    uint firstHalf = (tileSize + 1u) / 2u;
    uvec2 side = uvec2(quarter & 1u, quarter >> 1u);
    uvec2 origin = tile * tileSize + side * firstHalf;
    uvec2 extent = mix(uvec2(firstHalf), uvec2(tileSize - firstHalf), equal(side, uvec2(1u)));
    uvec2 end = min(origin + extent, push.size);
    uvec2 pixels = tileIndex < tileCount ? max(end, origin) - origin : uvec2(0u);

    uvec2 mask = uvec2(0u);
    uint runSlice = kNoSlice;
    vec3 lo = vec3(0.0), hi = vec3(0.0);
    for (uint i = 0u; i < pixels.x * pixels.y; ++i) {
        uvec2 pixel = origin + uvec2(i % pixels.x, i / pixels.x);
        float ndcDepth = texelFetch(depthBuffer, ivec2(pixel), 0).r;
        if (ndcDepth <= 0.0) continue;  // background
        float depth = viewDepthFromNdc(ndcDepth, push.grid.projectionNear);
        uint slice = sliceOfDepth(sliceNear, logRatio, push.grid.slices, depth);
        vec2 ndc = (vec2(pixel) + 0.5) / vec2(push.size) * 2.0 - 1.0;
        vec3 view = vec3(ndc * depth / push.projectionScale, -depth);
        if (slice == runSlice) {
            lo = min(lo, view);
            hi = max(hi, view);
            continue;
        }
        flushRun(quarterBox(clusterCount, runSlice * tileCount + tileIndex, quarter), runSlice, lo,
                 hi, mask);
        runSlice = slice;
        lo = view;
        hi = view;
    }
    flushRun(quarterBox(clusterCount, runSlice * tileCount + tileIndex, quarter), runSlice, lo, hi,
             mask);
    quarterMasks[gl_LocalInvocationIndex] = mask;
    memoryBarrierBuffer();
    barrier();
    if (tileIndex >= tileCount) return;

    // The tile's quarters merge: each quarter marks itself empty in the occupied clusters it
    // has no pixel of, and writes the cluster box (the union of its quarters) of every fourth.
    uint first = gl_LocalInvocationID.y * 4u;
    uvec2 quarters[4] = uvec2[4](quarterMasks[first], quarterMasks[first + 1u],
                                 quarterMasks[first + 2u], quarterMasks[first + 3u]);
    uvec2 tileMask = quarters[0] | quarters[1] | quarters[2] | quarters[3];
    if (quarter == 0u) tileMasks[tileIndex] = tileMask;
    uvec2 remaining = tileMask;
    for (uint k = 0u; any(notEqual(remaining, uvec2(0u))); ++k) {
        uint slice = remaining.x != 0u ? uint(findLSB(remaining.x))
                                       : 32u + uint(findLSB(remaining.y));
        remaining &= ~sliceBit(slice);
        uint cluster = slice * tileCount + tileIndex;
        if (!hasSlice(mask, slice)) {
            storeBox(quarterBox(clusterCount, cluster, quarter), vec3(kEmptyQuarterBound),
                     vec3(-kEmptyQuarterBound));
        }
        if (k % 4u != quarter) continue;
        vec3 boxLo = vec3(kEmptyQuarterBound), boxHi = vec3(-kEmptyQuarterBound);
        for (uint q = 0u; q < 4u; ++q) {
            if (!hasSlice(quarters[q], slice)) continue;
            uint at = quarterBox(clusterCount, cluster, q);
            for (uint c = 0u; c < 3u; ++c) {
                boxLo[c] = min(boxLo[c], clusterBounds[at + c]);
                boxHi[c] = max(boxHi[c], clusterBounds[at + 3u + c]);
            }
        }
        storeBox(cluster * CLUSTER_BOX_FLOATS, boxLo, boxHi);
    }
}
