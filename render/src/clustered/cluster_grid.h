#pragma once
// The cluster grid: screen tiles x exponential depth slices over the view frustum.
//
// View space looks down -Z; `depth` below is the positive distance along the view axis.
// Slice k spans depths [near * ratio^k, near * ratio^(k+1)) with ratio = (far/near)^(1/slices),
// so cells stay roughly cubical at every distance. Depths past `far` fall in the last slice.
#include <cmath>
#include <cstdint>
#include <vector>

namespace candela::render {

struct ClusterGridConfig {
    uint32_t tileSize = 64;  // pixels; see render/README.md for the measurements behind it
    uint32_t slices = 32;    // <= 64: a tile's occupied slices fit one 64-bit mask
};

struct ClusterGrid {
    uint32_t tileSize = 64;
    uint32_t tilesX = 0;
    uint32_t tilesY = 0;
    uint32_t slices = 32;
    float nearPlane = 0.05f;
    float farPlane = 500.0f;
    float logRatio = 1.0f;  // log(far / near) / slices

    // Tile boundaries as tangents: a point with view-space x, y at depth d is in column i when
    // columnTangent[i] <= x / d < columnTangent[i + 1], and row j when
    // rowTangent[j + 1] < y / d <= rowTangent[j] (pixel rows grow downwards).
    std::vector<float> columnTangent;
    std::vector<float> rowTangent;

    static ClusterGrid make(const ClusterGridConfig& config, uint32_t width, uint32_t height,
                            float projectionScaleX, float projectionScaleY, float nearPlane,
                            float farPlane);

    uint32_t clusterCount() const { return tilesX * tilesY * slices; }
    uint32_t tileCount() const { return tilesX * tilesY; }
    uint32_t clusterIndex(uint32_t x, uint32_t y, uint32_t slice) const {
        return (slice * tilesY + y) * tilesX + x;
    }
    float sliceDepth(uint32_t slice) const { return nearPlane * std::exp(logRatio * float(slice)); }
    // Clamped to [0, slices - 1]; depths below near land in slice 0.
    uint32_t sliceOf(float depth) const {
        if (!(depth > nearPlane)) return 0;
        float k = std::floor(std::log(depth / nearPlane) / logRatio);
        return k >= float(slices - 1) ? slices - 1 : uint32_t(k);
    }
};

}  // namespace candela::render
