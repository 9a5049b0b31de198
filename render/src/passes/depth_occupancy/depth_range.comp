#version 460
#extension GL_GOOGLE_include_directive : require
#include "depth_occupancy_bindings.h"
// The nearest and farthest geometry in view depth: the cluster grid spends its slices there.
#include "common/clusters.glsl"

// One invocation per 8x8 block of pixels, its min and max kept in registers and added with one
// pair of atomics: no shared memory or barrier (lavapipe runs shared atomics one lane at a
// time and a barrier turns the shader into coroutines).
layout(local_size_x = 8) in;
const uint kBlock = 8u;

layout(binding = DEPTH_RANGE_BINDING_DEPTH) uniform sampler2D depthBuffer;
// [0] min and [1] max view depth as ordered bits (cleared to 0xffffffff / 0 before).
layout(std430, binding = DEPTH_RANGE_BINDING_RANGE) buffer DepthRange { uint range[]; };

layout(push_constant) uniform Push {
    uvec2 size;
    float projectionNear;
} push;

void main() {
    uint blocksX = (push.size.x + kBlock - 1u) / kBlock;
    uint blocksY = (push.size.y + kBlock - 1u) / kBlock;
    uint block = gl_GlobalInvocationID.x;
    if (block >= blocksX * blocksY) return;
    uvec2 origin = uvec2(block % blocksX, block / blocksX) * kBlock;
    uvec2 end = min(origin + kBlock, push.size);
    float nearest = 3.0e38, farthest = 0.0;
    for (uint y = origin.y; y < end.y; ++y) {
        for (uint x = origin.x; x < end.x; ++x) {
            float ndcDepth = texelFetch(depthBuffer, ivec2(x, y), 0).r;
            if (ndcDepth <= 0.0) continue;  // background
            float depth = viewDepthFromNdc(ndcDepth, push.projectionNear);
            nearest = min(nearest, depth);
            farthest = max(farthest, depth);
        }
    }
    if (farthest > 0.0) {
        atomicMin(range[0], orderedBits(nearest));
        atomicMax(range[1], orderedBits(farthest));
    }
}
