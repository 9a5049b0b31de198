#version 460
#extension GL_GOOGLE_include_directive : require
#include "forward_transparent_bindings.h"
// Clustered light lists are built only for clusters that hold surfaces, from the G-buffer
// depth (depth_occupancy.comp). Blended surfaces are not in the G-buffer, so this pass
// rasterises them (in front of the opaque depth) and records, per cluster and quarter of its
// tile, the view-space box around their fragments; transparent_occupancy_merge.comp then adds
// those clusters and boxes to the opaque ones before light assignment. Without it a glass pane
// in front of empty space would find no lights in its clusters, and a pane just in front of an
// opaque surface would miss, in the quarter masks of its list entries, the lights that reach
// the pane but not the surface behind it.
#include "common/clusters.glsl"

layout(binding = TRANSPARENT_OCCUPANCY_BINDING_DEPTH) uniform sampler2D gbufferDepth;
// From depth_occupancy.comp: [2] sliceNear, [3] logRatio (float bits), the frame's slicing.
layout(std430, binding = TRANSPARENT_OCCUPANCY_BINDING_DEPTH_RANGE) readonly buffer DepthRange {
    uint range[];
};
// Ordered float bits (see orderedBits), per quarter b = 4 * cluster + quarter: mins at
// [3b + axis], maxs at [3 * (4 * clusterCount + b) + axis]; cleared to 0xffffffff / 0 before
// the pass.
layout(std430, binding = TRANSPARENT_OCCUPANCY_BINDING_BOUNDS) buffer TransparentBounds {
    uint bounds[];
};

layout(push_constant) uniform Draw {
    mat4 world;
    uint material;
    uint directionalCount;
    ClusterGridParams grid;
    uvec2 size;
    vec2 projectionScale;  // projection[0][0], projection[1][1]
} draw;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    // Reverse-Z, GREATER_OR_EQUAL: hidden behind the opaque surface when nearer to 0.
    if (gl_FragCoord.z < texelFetch(gbufferDepth, pixel, 0).r) return;
    float sliceNear = uintBitsToFloat(range[2]);
    float logRatio = uintBitsToFloat(range[3]);
    float depth = viewDepthFromNdc(gl_FragCoord.z, draw.grid.projectionNear);
    uint slice = sliceOfDepth(sliceNear, logRatio, draw.grid.slices, depth);
    uvec2 tile = uvec2(pixel) / draw.grid.tileSize;
    uint cluster = (slice * draw.grid.tilesY + tile.y) * draw.grid.tilesX + tile.x;
    uint clusterCount = draw.grid.tilesX * draw.grid.tilesY * draw.grid.slices;
    // The same pixel-centre reconstruction as depth_occupancy.comp.
    vec2 ndc = gl_FragCoord.xy / vec2(draw.size) * 2.0 - 1.0;
    vec3 view = vec3(ndc * depth / draw.projectionScale, -depth);
    uint box = 4u * cluster + quarterOfPixel(draw.grid.tileSize, uvec2(pixel));
    for (uint c = 0u; c < 3u; ++c) {
        atomicMin(bounds[3u * box + c], orderedBits(view[c]));
        atomicMax(bounds[3u * (4u * clusterCount + box) + c], orderedBits(view[c]));
    }
}
