#version 460
// One invocation per cluster: the write pass filled each list in whatever order its atomics
// ran; sorting restores ascending light order, so the clustered sum is the brute-force sum
// with zeros left out (the CPU path's order) and every frame is deterministic. Lists are short
// (tens of lights), so an insertion sort in place is enough.

layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer ClusterRanges { uvec2 clusterRanges[]; };
layout(std430, binding = 1) buffer LightIndices { uint lightIndices[]; };

layout(push_constant) uniform Push {
    uint clusterCount;
} push;

const uint kListOverflow = 0xffffffffu;

void main() {
    uint cluster = gl_GlobalInvocationID.x;
    if (cluster >= push.clusterCount) return;
    uvec2 range = clusterRanges[cluster];
    if (range.y == kListOverflow || range.y < 2u) return;
    for (uint i = range.x + 1u; i < range.x + range.y; ++i) {
        uint value = lightIndices[i];
        uint j = i;
        while (j > range.x && lightIndices[j - 1u] > value) {
            lightIndices[j] = lightIndices[j - 1u];
            --j;
        }
        lightIndices[j] = value;
    }
}
