#version 460
#extension GL_GOOGLE_include_directive : require
#include "light_assignment_bindings.h"
// One invocation per screen tile: reserves one contiguous block of the light index buffer for
// the lists of the tile's occupied clusters (one atomic per tile, not per cluster), writes each
// cluster's offset and count, and zeroes the counts so the write pass can use them as cursors.
// Only occupied clusters can hold lights (assign_lights.comp tests the occupancy bit), so the
// walk visits the set bits of the tile's mask; clusters occupied last frame but empty now get
// an empty range, which keeps every range the lighting pass can read current.
// A block that does not fit marks its clusters as overflowed: the lighting pass then evaluates
// every light there (nothing is dropped), and the renderer grows the buffer for the next frame
// from the total this pass accumulated.

layout(local_size_x = 64) in;

layout(std430, binding = ALLOCATE_BINDING_CLUSTER_COUNTS) coherent buffer ClusterCounts {
    uint clusterCounts[];
};
layout(std430, binding = ALLOCATE_BINDING_CLUSTER_RANGES) writeonly buffer ClusterRanges {
    uvec2 clusterRanges[];
};
// Index entries requested this frame; the host sets it to the directional light count, whose
// indices lead the buffer. It keeps counting past the capacity, so the host learns the size
// the frame needed.
layout(std430, binding = ALLOCATE_BINDING_LIST_USAGE) coherent buffer ListUsage { uint requested; };
layout(std430, binding = ALLOCATE_BINDING_OCCUPANCY) readonly buffer Occupancy {
    uvec2 tileMasks[];
};
// Each tile's mask of the previous frame (this pass replaces it).
layout(std430, binding = ALLOCATE_BINDING_PREVIOUS_OCCUPANCY) buffer PreviousOccupancy {
    uvec2 previousMasks[];
};

layout(push_constant) uniform Push {
    uint tileCount;
    uint capacity;  // entries in the light index buffer
} push;

const uint kListOverflow = 0xffffffffu;

void main() {
    uint tile = gl_GlobalInvocationID.x;
    if (tile >= push.tileCount) return;
    uvec2 mask = tileMasks[tile];
    uvec2 stale = previousMasks[tile] & ~mask;
    previousMasks[tile] = mask;
    for (uint half_ = 0u; half_ < 2u; ++half_) {
        for (uint bits = stale[half_]; bits != 0u; bits &= bits - 1u) {
            uint k = uint(findLSB(bits)) + 32u * half_;
            clusterRanges[k * push.tileCount + tile] = uvec2(0u);
        }
    }
    uint total = 0u;
    for (uint half_ = 0u; half_ < 2u; ++half_) {
        for (uint bits = mask[half_]; bits != 0u; bits &= bits - 1u) {
            uint k = uint(findLSB(bits)) + 32u * half_;
            total += clusterCounts[k * push.tileCount + tile];
        }
    }
    uint offset = total == 0u ? 0u : atomicAdd(requested, total);
    bool fits = offset + total <= push.capacity && offset + total >= offset;
    for (uint half_ = 0u; half_ < 2u; ++half_) {
        for (uint bits = mask[half_]; bits != 0u; bits &= bits - 1u) {
            uint k = uint(findLSB(bits)) + 32u * half_;
            uint cluster = k * push.tileCount + tile;
            uint count = clusterCounts[cluster];
            clusterRanges[cluster] =
                fits ? uvec2(offset, count) : uvec2(0u, count == 0u ? 0u : kListOverflow);
            offset += count;
            clusterCounts[cluster] = 0u;
        }
    }
}
