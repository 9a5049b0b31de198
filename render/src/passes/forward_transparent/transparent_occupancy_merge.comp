#version 460
#extension GL_GOOGLE_include_directive : require
#include "forward_transparent_bindings.h"
// Adds the clusters and quarter boxes of blended fragments (transparent_occupancy.frag) to the
// opaque occupancy (depth_occupancy.comp): one workgroup per tile, one invocation per slice.
// Each quarter's box then holds both its opaque pixels and its blended fragments, so the
// quarter masks of the light lists hold for the forward pass as for the deferred one.
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
    uint cluster = slice * tileCount + tileIndex;
    // A quarter without blended fragments still has its cleared max (0).
    bool blended = false;
    if (slice < push.grid.slices) {
        for (uint q = 0u; q < 4u; ++q) {
            blended = blended || bounds[3u * (4u * clusterCount + 4u * cluster + q)] != 0u;
        }
    }
    if (blended) {
        bool opaque = ((slice < 32u ? opaqueMask.x >> slice : opaqueMask.y >> (slice - 32u)) & 1u) != 0u;
        vec3 unionLo = vec3(kEmptyQuarterBound), unionHi = vec3(-kEmptyQuarterBound);
        for (uint q = 0u; q < 4u; ++q) {
            uint box = 4u * cluster + q;
            bool empty = bounds[3u * (4u * clusterCount + box)] == 0u;
            uint out_ = clusterCount * CLUSTER_BOX_FLOATS + cluster * CLUSTER_QUARTER_BOXES_FLOATS +
                        q * 6u;
            for (uint c = 0u; c < 3u; ++c) {
                float lo = empty ? kEmptyQuarterBound : fromOrderedBits(bounds[3u * box + c]);
                float hi = empty ? -kEmptyQuarterBound
                                 : fromOrderedBits(bounds[3u * (4u * clusterCount + box) + c]);
                // The opaque quarter's box (empty ones are min > max, which min/max keep).
                if (opaque) {
                    lo = min(lo, clusterBounds[out_ + c]);
                    hi = max(hi, clusterBounds[out_ + 3u + c]);
                }
                clusterBounds[out_ + c] = lo;
                clusterBounds[out_ + 3u + c] = hi;
                unionLo[c] = min(unionLo[c], lo);
                unionHi[c] = max(unionHi[c], hi);
            }
        }
        // The cluster's box: the union of its quarters, blended and opaque.
        for (uint c = 0u; c < 3u; ++c) {
            clusterBounds[cluster * CLUSTER_BOX_FLOATS + c] = unionLo[c];
            clusterBounds[cluster * CLUSTER_BOX_FLOATS + 3u + c] = unionHi[c];
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
