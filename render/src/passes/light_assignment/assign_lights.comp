#version 460
#extension GL_GOOGLE_include_directive : require
#include "light_assignment_bindings.h"
// Light-centric assignment, one invocation per light, run twice: the count pass adds the light
// to the count of every cluster it touches, the write pass (after allocate_lists.comp gave
// each cluster its range) stores the light's index there. The walk mirrors
// render/src/clustered/light_assignment.cpp: slice range from the light's depth extent, per
// slice the tile range of its widest cross-section, per cell the row and column planes, the
// occupancy bit and the boxes around the pixels of the cluster's quarters, which give the
// entry's quarter mask (light_list_entry.h).
#include "common/clusters.glsl"
#include "common/specialization_ids.h"
#include "common/light_buffer.glsl"
#include "common/light_cluster_tests.glsl"

layout(local_size_x = 64) in;

layout(constant_id = SPEC_ASSIGN_WRITE_PASS) const bool kWritePass = false;

layout(std430, binding = ASSIGN_BINDING_OCCUPANCY) readonly buffer Occupancy { uvec2 tileMasks[]; };
layout(std430, binding = ASSIGN_BINDING_CLUSTER_BOUNDS) readonly buffer ClusterBounds {
    float clusterBounds[];
};
layout(std430, binding = ASSIGN_BINDING_DEPTH_RANGE) readonly buffer DepthRange {
    uint depthRange[];
};
// Count pass: lights per cluster. Write pass: the cursor into each cluster's range.
layout(std430, binding = ASSIGN_BINDING_CLUSTER_COUNTS) coherent buffer ClusterCounts {
    uint clusterCounts[];
};
layout(std430, binding = ASSIGN_BINDING_CLUSTER_RANGES) readonly buffer ClusterRanges {
    uvec2 clusterRanges[];
};
layout(std430, binding = ASSIGN_BINDING_LIGHT_INDICES) writeonly buffer LightIndices {
    uint lightIndices[];
};

layout(push_constant) uniform Push {
    mat4 view;
    ClusterGridParams grid;
    uvec2 size;
    vec2 projectionScale;  // projection[0][0], projection[1][1]
    uint lightCount;
    uint lightCapacity;
} push;

const float kSliceDepthMargin = 1e-3;
const float kPixelBoundsMargin = 1e-4;  // relative to depth
const uint kListOverflow = 0xffffffffu;

float sliceNear;
float logRatio;

float sliceDepth(uint slice) {
    return slice == 0u ? 0.0 : sliceNear * exp(logRatio * float(slice));
}

// Tile boundary i as a tangent x / d (columns) or y / d (rows), as ClusterGrid::make.
float columnTangent(uint i) {
    float p = float(min(i * push.grid.tileSize, push.size.x));
    return (2.0 * p / float(push.size.x) - 1.0) / push.projectionScale.x;
}
float rowTangent(uint j) {
    float p = float(min(j * push.grid.tileSize, push.size.y));
    return (2.0 * p / float(push.size.y) - 1.0) / push.projectionScale.y;
}

// Tiles whose pixels the tangent interval [lo, hi] may cover, widened by one tile for rounding
// (the plane tests decide). False when the interval misses the screen.
bool tileSpan(float lo, float hi, float scale, uint pixels, uint tiles, out uint first,
              out uint last) {
    float a = (lo * scale + 1.0) * 0.5 * float(pixels);
    float b = (hi * scale + 1.0) * 0.5 * float(pixels);
    float pLo = min(a, b), pHi = max(a, b);
    float tile = float(push.grid.tileSize);
    if (!(pHi >= -tile) || !(pLo <= float(pixels) + tile)) return false;
    first = uint(clamp(floor(pLo / tile) - 1.0, 0.0, float(tiles - 1u)));
    last = uint(clamp(floor(pHi / tile) + 1.0, 0.0, float(tiles - 1u)));
    return true;
}

// The box [lo, hi] padded for the lighting shader's own (world-space) reconstruction of the
// points inside it.
vec3 pixelBoxPad(vec3 lo) {
    return vec3(kPixelBoundsMargin * (1.0 - lo.z));
}

vec3 boundsMin(uint at) {
    return vec3(clusterBounds[at], clusterBounds[at + 1u], clusterBounds[at + 2u]);
}
vec3 boundsMax(uint at) {
    return vec3(clusterBounds[at + 3u], clusterBounds[at + 4u], clusterBounds[at + 5u]);
}

// Quarter q's bit when the light's bounding shape touches its box (at: the box's first float).
uint quarterBit(LightBounds b, uint at, uint q) {
    vec3 lo = boundsMin(at), hi = boundsMax(at);
    if (lo.x > hi.x) return 0u;  // no pixel in this quarter
    vec3 pad = pixelBoxPad(lo);
    return boundingShapeTouchesBox(b, lo - pad, hi + pad) ? 1u << (LIGHT_ENTRY_QUARTER_SHIFT + q)
                                                          : 0u;
}

// The entry's quarter bits for the cluster (0: the light reaches none of its pixels), as
// quarterMask in light_assignment.cpp: the exact test on the cluster's box, then the
// bounding-shape test per quarter. Written without loops: llvmpipe (lavapipe) stops a shader's
// loops after 65,535 iterations in total, counting at least one per loop entered even with
// every lane inactive (the capsule search in lightTouchesBox); a light over every cluster of a
// 256 x 256 frame already spends two per cluster, 32,768, and a loop per quarter test would
// take it past the limit and silently drop clusters.
uint quarterMask(LightBounds b, uint cluster, uint clusterCount) {
    vec3 lo = boundsMin(cluster * CLUSTER_BOX_FLOATS), hi = boundsMax(cluster * CLUSTER_BOX_FLOATS);
    vec3 pad = pixelBoxPad(lo);
    if (!lightTouchesBox(b, lo - pad, hi + pad)) return 0u;
    uint at = clusterCount * CLUSTER_BOX_FLOATS + cluster * CLUSTER_QUARTER_BOXES_FLOATS;
    return quarterBit(b, at, 0u) | quarterBit(b, at + 6u, 1u) | quarterBit(b, at + 12u, 2u) |
           quarterBit(b, at + 18u, 3u);
}

// `entry`: light index | quarter mask.
void emit(uint cluster, uint entry) {
    if (!kWritePass) {
        atomicAdd(clusterCounts[cluster], 1u);
        return;
    }
    uvec2 range = clusterRanges[cluster];
    if (range.y == kListOverflow) return;  // the lighting pass takes every light there
    uint slot = atomicAdd(clusterCounts[cluster], 1u);
    lightIndices[range.x + slot] = entry;
}

void main() {
    uint lightIndex = gl_GlobalInvocationID.x;
    if (lightIndex >= push.lightCount) return;
    Light light = loadLight(lightIndex, push.lightCapacity);
    if (lightInEveryCluster(light.type)) return;  // listed once for every pixel
    sliceNear = uintBitsToFloat(depthRange[2]);
    logRatio = uintBitsToFloat(depthRange[3]);
    LightBounds b = lightBoundsInView(light, push.view);

    const uint tileCount = push.grid.tilesX * push.grid.tilesY;
    const float centerDepth = -b.center.z;
    const float nearDepth = centerDepth - b.radius;
    const float farDepth = centerDepth + b.radius;
    if (farDepth < push.grid.projectionNear) return;  // wholly behind the near plane
    const uint slices = push.grid.slices;
    uint firstSlice = sliceOfDepth(sliceNear, logRatio, slices, nearDepth * (1.0 - kSliceDepthMargin));
    uint lastSlice = sliceOfDepth(sliceNear, logRatio, slices, farDepth * (1.0 + kSliceDepthMargin));
    for (uint k = firstSlice; k <= lastSlice; ++k) {
        const float z0 = sliceDepth(k) * (1.0 - kSliceDepthMargin);
        const float z1 = k + 1u == slices ? max(farDepth, sliceDepth(k)) * 2.0
                                          : sliceDepth(k + 1u) * (1.0 + kSliceDepthMargin);
        const float dz = clamp(centerDepth, z0, z1) - centerDepth;
        const float crossRadius = sqrt(max(b.radius * b.radius - dz * dz, 0.0));
        const float depthLo = max(max(z0, nearDepth), 1e-6);
        const float depthHi = min(z1, farDepth);
        if (depthHi < depthLo) continue;
        vec2 lo = min((b.center.xy - crossRadius) / depthLo, (b.center.xy - crossRadius) / depthHi);
        vec2 hi = max((b.center.xy + crossRadius) / depthLo, (b.center.xy + crossRadius) / depthHi);
        uint x0, x1, y0, y1;
        if (!tileSpan(lo.x, hi.x, push.projectionScale.x, push.size.x, push.grid.tilesX, x0, x1) ||
            !tileSpan(lo.y, hi.y, push.projectionScale.y, push.size.y, push.grid.tilesY, y0, y1)) {
            continue;
        }
        for (uint y = y0; y <= y1; ++y) {
            const float top = rowTangent(y), bottom = rowTangent(y + 1u);
            // Row planes through the camera: bottom <= y/d <= top.
            if (!lightReachesPositiveSide(b, normalize(vec3(0.0, -1.0, -top))) ||
                !lightReachesPositiveSide(b, normalize(vec3(0.0, 1.0, bottom)))) {
                continue;
            }
            for (uint x = x0; x <= x1; ++x) {
                const uint tile = y * push.grid.tilesX + x;
                const uvec2 mask = tileMasks[tile];
                if (((k < 32u ? mask.x >> k : mask.y >> (k - 32u)) & 1u) == 0u) continue;
                const float left = columnTangent(x), right = columnTangent(x + 1u);
                if (!lightReachesPositiveSide(b, normalize(vec3(1.0, 0.0, left))) ||
                    !lightReachesPositiveSide(b, normalize(vec3(-1.0, 0.0, -right)))) {
                    continue;
                }
                const uint cluster = k * tileCount + tile;
                const uint quarters = quarterMask(b, cluster, tileCount * slices);
                if (quarters == 0u) continue;
                emit(cluster, lightIndex | quarters);
            }
        }
    }
}
