#include "clustered/cluster_grid.h"

#include <algorithm>

namespace candela::render {

ClusterGrid ClusterGrid::make(const ClusterGridConfig& config, uint32_t width, uint32_t height,
                              float projectionScaleX, float projectionScaleY, float nearPlane,
                              float farPlane) {
    ClusterGrid g;
    g.tileSize = std::max(config.tileSize, 1u);
    g.slices = std::clamp(config.slices, 1u, 64u);
    g.tilesX = (width + g.tileSize - 1) / g.tileSize;
    g.tilesY = (height + g.tileSize - 1) / g.tileSize;
    g.nearPlane = nearPlane;
    g.farPlane = std::max(farPlane, nearPlane * 1.001f);
    g.logRatio = std::log(g.farPlane / g.nearPlane) / float(g.slices);
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
