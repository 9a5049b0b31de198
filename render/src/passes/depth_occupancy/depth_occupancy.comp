#version 460
#extension GL_GOOGLE_include_directive : require
// One workgroup per screen tile: which depth slices of the tile hold geometry, as a 64-bit
// mask. Light assignment skips the empty clusters, so they cost nothing to light.
#include "common/clusters.glsl"

layout(local_size_x = 16, local_size_y = 16) in;

layout(binding = 0) uniform sampler2D depthBuffer;
layout(std430, binding = 1) writeonly buffer Occupancy { uvec2 tileMasks[]; };

layout(push_constant) uniform Push {
    ClusterGridParams grid;
    uvec2 size;
} push;

shared uint maskLow;
shared uint maskHigh;

void main() {
    if (gl_LocalInvocationIndex == 0u) {
        maskLow = 0u;
        maskHigh = 0u;
    }
    barrier();
    uvec2 tile = gl_WorkGroupID.xy;
    uvec2 origin = tile * push.grid.tileSize;
    for (uint y = gl_LocalInvocationID.y; y < push.grid.tileSize; y += 16u) {
        for (uint x = gl_LocalInvocationID.x; x < push.grid.tileSize; x += 16u) {
            uvec2 pixel = origin + uvec2(x, y);
            if (any(greaterThanEqual(pixel, push.size))) continue;
            float ndcDepth = texelFetch(depthBuffer, ivec2(pixel), 0).r;
            if (ndcDepth <= 0.0) continue;  // background
            uint slice = sliceOfDepth(push.grid, viewDepthFromNdc(ndcDepth, push.grid.nearPlane));
            if (slice < 32u) {
                atomicOr(maskLow, 1u << slice);
            } else {
                atomicOr(maskHigh, 1u << (slice - 32u));
            }
        }
    }
    barrier();
    if (gl_LocalInvocationIndex == 0u) {
        tileMasks[tile.y * push.grid.tilesX + tile.x] = uvec2(maskLow, maskHigh);
    }
}
