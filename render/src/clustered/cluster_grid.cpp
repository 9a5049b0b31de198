#include "clustered/cluster_grid.h"

#include <algorithm>

namespace candela::render {

uint32_t ClusterGrid::tileSizeFitting(uint32_t preferredTileSize, uint32_t slices, uint32_t width,
                                      uint32_t height, uint64_t bytesPerCluster,
                                      uint64_t maxBufferBytes) {
    uint32_t tile = std::max(preferredTileSize, 1u);
    auto bytes = [&](uint64_t t) {
        return ((width + t - 1) / t) * ((height + t - 1) / t) * uint64_t(slices) * bytesPerCluster;
    };
    while (bytes(tile) > maxBufferBytes && tile < std::max(width, height))
        tile *= 2;
    return tile;
}

ClusterGrid ClusterGrid::make(uint32_t tileSize, uint32_t slices, uint32_t width, uint32_t height,
                              float projectionScaleX, float projectionScaleY, float nearPlane,
                              float farPlane) {
    ClusterGrid g;
    g.tileSize = std::max(tileSize, 1u);
    g.slices = std::clamp(slices, 1u, 64u);
    g.tilesX = (width + g.tileSize - 1) / g.tileSize;
    g.tilesY = (height + g.tileSize - 1) / g.tileSize;
    g.nearPlane = nearPlane;
    g.sliceNear = nearPlane;
    g.logRatio = std::log(std::max(farPlane, nearPlane * 1.01f) / nearPlane) / float(g.slices);
    // ndc_x = projectionScaleX * x / d and pixel = (ndc + 1) / 2 * size, so the boundary at
    // pixel p has x / d = (2 p / width - 1) / projectionScaleX. For y the projection flips
    // (Vulkan's y points down), so projectionScaleY is negative and rows count downwards.
    for (uint32_t i = 0; i <= g.tilesX; ++i) {
        float p = float(std::min(i * g.tileSize, width));
        g.columnTangent.push_back((2.0f * p / float(width) - 1.0f) / projectionScaleX);
    }
    for (uint32_t j = 0; j <= g.tilesY; ++j) {
        float p = float(std::min(j * g.tileSize, height));
        g.rowTangent.push_back((2.0f * p / float(height) - 1.0f) / projectionScaleY);
    }
    return g;
}

}  // namespace candela::render
