// Cluster lookup shared by the depth-occupancy and lighting passes (matches cluster_grid.h).
#ifndef CANDELA_CLUSTERS_GLSL
#define CANDELA_CLUSTERS_GLSL

struct ClusterGridParams {
    uint tileSize;
    uint tilesX;
    uint tilesY;
    uint slices;
    float nearPlane;
    float logRatio;  // log(far / near) / slices
};

// Reverse-Z with an infinite far plane: ndc depth = near / view depth.
float viewDepthFromNdc(float ndcDepth, float nearPlane) {
    return nearPlane / ndcDepth;
}

uint sliceOfDepth(ClusterGridParams g, float depth) {
    if (!(depth > g.nearPlane)) return 0u;
    float k = floor(log(depth / g.nearPlane) / g.logRatio);
    return uint(min(k, float(g.slices - 1u)));
}

#endif
