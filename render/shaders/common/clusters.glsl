// Cluster lookup shared by the depth passes and the lighting pass (matches cluster_grid.h).
#ifndef CANDELA_CLUSTERS_GLSL
#define CANDELA_CLUSTERS_GLSL

#include "common/light_list_entry.h"

struct ClusterGridParams {
    uint tileSize;
    uint tilesX;
    uint tilesY;
    uint slices;
    float projectionNear;  // of the reverse-Z projection
    float sliceNear;       // where the exponential slices start (the nearest geometry)
    float logRatio;        // log(far / sliceNear) / slices
    uint pad;
};

// Reverse-Z with an infinite far plane: ndc depth = near / view depth.
float viewDepthFromNdc(float ndcDepth, float projectionNear) {
    return projectionNear / ndcDepth;
}

// Slice k >= 1 spans [sliceNear * r^k, sliceNear * r^(k+1)); slice 0 everything nearer.
uint sliceOfDepth(float sliceNear, float logRatio, uint slices, float depth) {
    if (!(depth > sliceNear)) return 0u;
    float k = floor(log(depth / sliceNear) / logRatio);
    return uint(min(k, float(slices - 1u)));
}

// The cluster holding a pixel at an ndc depth, with the slicing the depth occupancy pass
// measured (depthRange[2..3]): the one lookup the lighting and forward passes share.
uint clusterOfPixel(ClusterGridParams grid, uvec2 pixel, float ndcDepth, float sliceNear,
                    float logRatio) {
    uvec2 tile = pixel / grid.tileSize;
    float viewDepth = viewDepthFromNdc(ndcDepth, grid.projectionNear);
    uint slice = sliceOfDepth(sliceNear, logRatio, grid.slices, viewDepth);
    return (slice * grid.tilesY + tile.y) * grid.tilesX + tile.x;
}

// Which quarter of its screen tile a pixel lies in: (right half) + 2 * (lower half). List
// entries carry one bit per quarter (light_list_entry.h); the occupancy pass boxes each
// quarter's pixels, the assignment tests lights against those boxes.
uint quarterOfPixel(uint tileSize, uvec2 pixel) {
    uvec2 half_ = (pixel % tileSize) * 2u / tileSize;
    return half_.x + 2u * half_.y;
}

// The bit a pixel's list entries must carry for it to evaluate their light.
uint quarterBitOfPixel(ClusterGridParams grid, uvec2 pixel) {
    return 1u << (LIGHT_ENTRY_QUARTER_SHIFT + quarterOfPixel(grid.tileSize, pixel));
}

// Light index of a list entry whose quarter bits include `quarterBit`, else kNoLight: the one
// masked read the lighting and forward passes share.
const uint kNoLight = 0xffffffffu;
uint lightOfEntry(uint entry, uint quarterBit) {
    return (entry & quarterBit) != 0u ? entry & LIGHT_ENTRY_INDEX_MASK : kNoLight;
}

// Bounds of a quarter without pixels: min above max on every axis, so it touches no light.
const float kEmptyQuarterBound = 3.0e38;

// Order-preserving float bits: uint atomics on them give float min/max.
uint orderedBits(float f) {
    uint u = floatBitsToUint(f);
    return (u & 0x80000000u) != 0u ? ~u : (u | 0x80000000u);
}

float fromOrderedBits(uint u) {
    return uintBitsToFloat((u & 0x80000000u) != 0u ? (u & 0x7fffffffu) : ~u);
}

#endif
