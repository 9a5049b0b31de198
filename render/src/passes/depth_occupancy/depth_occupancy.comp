#version 460
#extension GL_GOOGLE_include_directive : require
#include "depth_occupancy_bindings.h"
// One workgroup per screen tile. For each depth slice of the tile: whether any pixel lies in
// it (a 64-bit mask per tile) and, per quarter of the tile, the view-space box around those
// pixels. Light assignment skips empty clusters and tests lights against the boxes of the
// surfaces actually there, so light lists shrink to the depths present and each entry says
// which quarters its light reaches (light_list_entry.h).
#include "common/clusters.glsl"

// Each invocation takes 2x2 pixels at a time and merges those that share a slice and quarter
// before its shared-memory atomics: lavapipe runs a lane's atomics one by one, and one per
// pixel and axis made this pass a fifth of the games' frames (docs/frame-budget.md).
layout(local_size_x = 8, local_size_y = 8) in;
const uint kInvocations = 64u;

layout(binding = OCCUPANCY_BINDING_DEPTH) uniform sampler2D depthBuffer;
layout(std430, binding = OCCUPANCY_BINDING_TILE_MASKS) writeonly buffer Occupancy {
    uvec2 tileMasks[];
};
// Per cluster, min xyz and max xyz of its pixels in view space, then per cluster and quarter
// the same, kEmptyQuarterBound-empty for a quarter without pixels (light_list_entry.h;
// unwritten where unoccupied).
layout(std430, binding = OCCUPANCY_BINDING_CLUSTER_BOUNDS) writeonly buffer ClusterBounds {
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

const uint kMaxSlices = 64u;
shared uint maskLow;
shared uint maskHigh;
// Order-preserving float bits (see orderedBits), so uint atomics give float min/max.
// Per slice and quarter: [(slice * 4 + quarter) * 3 + axis].
shared uint boundsMin[kMaxSlices * 12u];
shared uint boundsMax[kMaxSlices * 12u];

const uint kNoBox = 0xffffffffu;

// Widens box `box` (its first bounds index) to [lo, hi]; nothing for kNoBox.
void addToBox(uint box, vec3 lo, vec3 hi) {
    if (box == kNoBox) return;
    for (uint c = 0u; c < 3u; ++c) {
        atomicMin(boundsMin[box + c], orderedBits(lo[c]));
        atomicMax(boundsMax[box + c], orderedBits(hi[c]));
    }
}

void main() {
    if (gl_LocalInvocationIndex == 0u) {
        maskLow = 0u;
        maskHigh = 0u;
    }
    for (uint i = gl_LocalInvocationIndex; i < kMaxSlices * 12u; i += kInvocations) {
        boundsMin[i] = 0xffffffffu;
        boundsMax[i] = 0u;
    }
    barrier();
    // Slices span the depths present: from the nearest to the farthest geometry.
    float minDepth = range[0] == 0xffffffffu ? push.grid.projectionNear : fromOrderedBits(range[0]);
    float maxDepth = range[1] == 0u ? minDepth : fromOrderedBits(range[1]);
    float sliceNear = max(minDepth, push.grid.projectionNear);
    float logRatio = log(max(maxDepth, sliceNear * 1.01) / sliceNear) / float(push.grid.slices);
    if (gl_WorkGroupID.xy == uvec2(0u) && gl_LocalInvocationIndex == 0u) {
        range[2] = floatBitsToUint(sliceNear);
        range[3] = floatBitsToUint(logRatio);
    }
    uvec2 tile = gl_WorkGroupID.xy;
    uvec2 origin = tile * push.grid.tileSize;
    uvec2 mask = uvec2(0u);
    for (uint y = 2u * gl_LocalInvocationID.y; y < push.grid.tileSize; y += 16u) {
        for (uint x = 2u * gl_LocalInvocationID.x; x < push.grid.tileSize; x += 16u) {
            // The quad's pixels, merged while they fall in the same slice and quarter.
            uint pendingBox = kNoBox;
            vec3 lo = vec3(0.0), hi = vec3(0.0);
            for (uint q = 0u; q < 4u; ++q) {
                uvec2 pixel = origin + uvec2(x + (q & 1u), y + (q >> 1u));
                if (any(greaterThanEqual(pixel, push.size))) continue;
                float ndcDepth = texelFetch(depthBuffer, ivec2(pixel), 0).r;
                if (ndcDepth <= 0.0) continue;  // background
                float depth = viewDepthFromNdc(ndcDepth, push.grid.projectionNear);
                uint slice = sliceOfDepth(sliceNear, logRatio, push.grid.slices, depth);
                mask |= slice < 32u ? uvec2(1u << slice, 0u) : uvec2(0u, 1u << (slice - 32u));
                vec2 ndc = (vec2(pixel) + 0.5) / vec2(push.size) * 2.0 - 1.0;
                vec3 view = vec3(ndc * depth / push.projectionScale, -depth);
                uint box = (slice * 4u + quarterOfPixel(push.grid.tileSize, pixel)) * 3u;
                if (box == pendingBox) {
                    lo = min(lo, view);
                    hi = max(hi, view);
                    continue;
                }
                addToBox(pendingBox, lo, hi);
                pendingBox = box;
                lo = view;
                hi = view;
            }
            addToBox(pendingBox, lo, hi);
        }
    }
    if (mask.x != 0u) atomicOr(maskLow, mask.x);
    if (mask.y != 0u) atomicOr(maskHigh, mask.y);
    barrier();
    uint tileIndex = tile.y * push.grid.tilesX + tile.x;
    if (gl_LocalInvocationIndex == 0u) tileMasks[tileIndex] = uvec2(maskLow, maskHigh);
    uint tileCount = push.grid.tilesX * push.grid.tilesY;
    uint clusterCount = tileCount * push.grid.slices;
    for (uint i = gl_LocalInvocationIndex; i < push.grid.slices * 4u; i += kInvocations) {
        uint slice = i / 4u;
        uint occupied = slice < 32u ? maskLow >> slice : maskHigh >> (slice - 32u);
        if ((occupied & 1u) == 0u) continue;  // nothing in this cluster
        uint cluster = slice * tileCount + tileIndex;
        if (i % 4u == 0u) {
            // The cluster's box: its quarters' union (the cleared values are neutral).
            for (uint c = 0u; c < 3u; ++c) {
                uint lo = min(min(boundsMin[i * 3u + c], boundsMin[i * 3u + 3u + c]),
                              min(boundsMin[i * 3u + 6u + c], boundsMin[i * 3u + 9u + c]));
                uint hi = max(max(boundsMax[i * 3u + c], boundsMax[i * 3u + 3u + c]),
                              max(boundsMax[i * 3u + 6u + c], boundsMax[i * 3u + 9u + c]));
                clusterBounds[cluster * CLUSTER_BOX_FLOATS + c] = fromOrderedBits(lo);
                clusterBounds[cluster * CLUSTER_BOX_FLOATS + 3u + c] = fromOrderedBits(hi);
            }
        }
        uint out_ = clusterCount * CLUSTER_BOX_FLOATS + cluster * CLUSTER_QUARTER_BOXES_FLOATS +
                    (i % 4u) * 6u;
        bool empty = boundsMax[i * 3u] == 0u;  // no pixel in this quarter
        for (uint c = 0u; c < 3u; ++c) {
            clusterBounds[out_ + c] =
                empty ? kEmptyQuarterBound : fromOrderedBits(boundsMin[i * 3u + c]);
            clusterBounds[out_ + 3u + c] =
                empty ? -kEmptyQuarterBound : fromOrderedBits(boundsMax[i * 3u + c]);
        }
    }
}
