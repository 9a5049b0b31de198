#version 460
#extension GL_GOOGLE_include_directive : require
#include "depth_occupancy_bindings.h"
// The nearest and farthest geometry in view depth: the cluster grid spends its slices there.
#include "common/clusters.glsl"

layout(local_size_x = 16, local_size_y = 16) in;

layout(binding = DEPTH_RANGE_BINDING_DEPTH) uniform sampler2D depthBuffer;
// [0] min and [1] max view depth as ordered bits (cleared to 0xffffffff / 0 before).
layout(std430, binding = DEPTH_RANGE_BINDING_RANGE) buffer DepthRange { uint range[]; };

layout(push_constant) uniform Push {
    uvec2 size;
    float projectionNear;
} push;

shared uint groupMin;
shared uint groupMax;

void main() {
    if (gl_LocalInvocationIndex == 0u) {
        groupMin = 0xffffffffu;
        groupMax = 0u;
    }
    barrier();
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (all(lessThan(pixel, push.size))) {
        float ndcDepth = texelFetch(depthBuffer, ivec2(pixel), 0).r;
        if (ndcDepth > 0.0) {
            uint bits = orderedBits(viewDepthFromNdc(ndcDepth, push.projectionNear));
            atomicMin(groupMin, bits);
            atomicMax(groupMax, bits);
        }
    }
    barrier();
    if (gl_LocalInvocationIndex == 0u && groupMax != 0u) {
        atomicMin(range[0], groupMin);
        atomicMax(range[1], groupMax);
    }
}
