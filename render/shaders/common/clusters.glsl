// Cluster lookup shared by the depth passes and the lighting pass (matches cluster_grid.h).
#ifndef CANDELA_CLUSTERS_GLSL
#define CANDELA_CLUSTERS_GLSL

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

// Order-preserving float bits: uint atomics on them give float min/max.
uint orderedBits(float f) {
    uint u = floatBitsToUint(f);
    return (u & 0x80000000u) != 0u ? ~u : (u | 0x80000000u);
}

float fromOrderedBits(uint u) {
    return uintBitsToFloat((u & 0x80000000u) != 0u ? (u & 0x7fffffffu) : ~u);
}

#endif
