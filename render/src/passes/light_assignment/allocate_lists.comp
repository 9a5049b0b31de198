#version 460
// One invocation per screen tile: reserves one contiguous block of the light index buffer for
// the tile's 64 cluster lists (one atomic per tile, not per cluster), writes each cluster's
// offset and count, and zeroes the counts so the write pass can use them as cursors. A block
// that does not fit marks its clusters as overflowed: the lighting pass then evaluates every
// light there (nothing is dropped), and the renderer grows the buffer for the next frame from
// the total this pass accumulated.

layout(local_size_x = 64) in;

layout(std430, binding = 0) coherent buffer ClusterCounts { uint clusterCounts[]; };
layout(std430, binding = 1) writeonly buffer ClusterRanges { uvec2 clusterRanges[]; };
// [0]: index entries requested this frame; starts at the directional light count, whose
// indices lead the buffer. It keeps counting past the capacity, so the host learns the size
// the frame needed.
layout(std430, binding = 2) coherent buffer ListUsage { uint requested; };

layout(push_constant) uniform Push {
    uint tileCount;
    uint slices;
    uint capacity;  // entries in the light index buffer
} push;

const uint kListOverflow = 0xffffffffu;

void main() {
    uint tile = gl_GlobalInvocationID.x;
    if (tile >= push.tileCount) return;
    uint total = 0u;
    for (uint k = 0u; k < push.slices; ++k) total += clusterCounts[k * push.tileCount + tile];
    uint offset = total == 0u ? 0u : atomicAdd(requested, total);
    bool fits = offset + total <= push.capacity && offset + total >= offset;
    for (uint k = 0u; k < push.slices; ++k) {
        uint cluster = k * push.tileCount + tile;
        uint count = clusterCounts[cluster];
        clusterRanges[cluster] = fits ? uvec2(offset, count)
                                      : uvec2(0u, count == 0u ? 0u : kListOverflow);
        offset += count;
        clusterCounts[cluster] = 0u;
    }
}
