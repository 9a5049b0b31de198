#version 460
#extension GL_GOOGLE_include_directive : require
#include "light_assignment_bindings.h"
// One workgroup per screen tile, one invocation per depth slice: the write pass filled each
// list in whatever order its atomics ran; sorting restores ascending light order, so the
// clustered sum is the brute-force sum with zeros left out (the CPU path's order) and every
// frame is deterministic. Lists are short (tens of lights), so an insertion sort in place is
// enough; entries compare by light index (the low bits, under the quarter mask of
// light_list_entry.h). It also zeroes the write cursors, so the counts start at zero next frame without a
// fill. (A variant with one invocation walking all of a tile's clusters gave images that
// changed run to run in the 16,384-light test on lavapipe, cause not found; one invocation
// per cluster is deterministic there.)

#extension GL_GOOGLE_include_directive : require
#include "common/light_list_entry.h"

layout(local_size_x = 64) in;

layout(std430, binding = SORT_BINDING_CLUSTER_RANGES) readonly buffer ClusterRanges {
    uvec2 clusterRanges[];
};
layout(std430, binding = SORT_BINDING_LIGHT_INDICES) buffer LightIndices { uint lightIndices[]; };
layout(std430, binding = SORT_BINDING_CLUSTER_COUNTS) writeonly buffer ClusterCounts {
    uint clusterCounts[];
};
layout(std430, binding = SORT_BINDING_OCCUPANCY) readonly buffer Occupancy { uvec2 tileMasks[]; };

layout(push_constant) uniform Push {
    uint tileCount;
} push;
// slices <= 64 (ClusterGrid), so every slice of the tile has an invocation.

const uint kListOverflow = 0xffffffffu;

void main() {
    uint tile = gl_WorkGroupID.x;
    uint slice = gl_LocalInvocationIndex;
    uvec2 mask = tileMasks[tile];
    if (((slice < 32u ? mask.x >> slice : mask.y >> (slice - 32u)) & 1u) == 0u) return;
    uint cluster = slice * push.tileCount + tile;
    uvec2 range = clusterRanges[cluster];
    if (range.y == 0u) return;
    clusterCounts[cluster] = 0u;
    if (range.y == kListOverflow) return;
    for (uint i = range.x + 1u; i < range.x + range.y; ++i) {
        uint value = lightIndices[i];
        uint key = value & LIGHT_ENTRY_INDEX_MASK;
        uint j = i;
        while (j > range.x && (lightIndices[j - 1u] & LIGHT_ENTRY_INDEX_MASK) > key) {
            lightIndices[j] = lightIndices[j - 1u];
            --j;
        }
        lightIndices[j] = value;
    }
}
