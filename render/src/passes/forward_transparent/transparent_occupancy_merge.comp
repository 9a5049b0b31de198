#version 460
#extension GL_GOOGLE_include_directive : require
#include "forward_transparent_bindings.h"
// Adds the clusters and boxes of blended fragments (transparent_occupancy.frag) to the opaque
// occupancy (depth_occupancy.comp): one workgroup per tile, one invocation per slice.
#include "common/clusters.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = MERGE_BINDING_TILE_MASKS) buffer Occupancy { uvec2 tileMasks[]; };
layout(std430, binding = MERGE_BINDING_CLUSTER_BOUNDS) buffer ClusterBounds {
    float clusterBounds[];
};
layout(std430, binding = MERGE_BINDING_TRANSPARENT_BOUNDS) readonly buffer TransparentBounds {
    uint bounds[];
};

layout(push_constant) uniform Push {
    ClusterGridParams grid;
} push;

shared uint addedLow;
shared uint addedHigh;

void main() {
    if (gl_LocalInvocationIndex == 0u) {
        addedLow = 0u;
        addedHigh = 0u;
    }
    barrier();
    uint tileIndex = gl_WorkGroupID.y * push.grid.tilesX + gl_WorkGroupID.x;
    uint tileCount = push.grid.tilesX * push.grid.tilesY;
    uint clusterCount = tileCount * push.grid.slices;
    uint slice = gl_LocalInvocationIndex;
    uvec2 opaqueMask = tileMasks[tileIndex];
    if (slice < push.grid.slices && bounds[3u * (clusterCount + slice * tileCount + tileIndex)] != 0u) {
        uint cluster = slice * tileCount + tileIndex;
        bool opaque = ((slice < 32u ? opaqueMask.x >> slice : opaqueMask.y >> (slice - 32u)) & 1u) != 0u;
        for (uint c = 0u; c < 3u; ++c) {
            float lo = fromOrderedBits(bounds[3u * cluster + c]);
            float hi = fromOrderedBits(bounds[3u * (clusterCount + cluster) + c]);
            if (opaque) {
                lo = min(lo, clusterBounds[cluster * 6u + c]);
                hi = max(hi, clusterBounds[cluster * 6u + 3u + c]);
            }
            clusterBounds[cluster * 6u + c] = lo;
            clusterBounds[cluster * 6u + 3u + c] = hi;
        }
        if (slice < 32u) {
            atomicOr(addedLow, 1u << slice);
        } else {
            atomicOr(addedHigh, 1u << (slice - 32u));
        }
    }
    barrier();
    if (gl_LocalInvocationIndex == 0u) {
        tileMasks[tileIndex] = opaqueMask | uvec2(addedLow, addedHigh);
    }
}
