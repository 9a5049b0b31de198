#pragma once
// The cluster grid: screen tiles x exponential depth slices over the view frustum.
//
// View space looks down -Z; `depth` below is the positive distance along the view axis.
// The slices cover the depths present in the frame (the depth-range pass measures them):
// slice k >= 1 spans [sliceNear * r^k, sliceNear * r^(k+1)) with r = exp(logRatio), slice 0
// everything nearer, the last slice everything farther. Exponential spacing keeps cells
// roughly cubical at every distance.
#include <cmath>
#include <cstdint>
#include <vector>

namespace candela::render {

struct ClusterGrid {
    uint32_t tileSize = 16;
    uint32_t tilesX = 0;
    uint32_t tilesY = 0;
    uint32_t slices = 64;
    float nearPlane = 0.05f;  // the projection's near plane
    float sliceNear = 0.05f;
    float logRatio = 1.0f;

    // Tile boundaries as tangents: a point with view-space x, y at depth d is in column i when
    // columnTangent[i] <= x / d < columnTangent[i + 1], and row j when
    // rowTangent[j + 1] < y / d <= rowTangent[j] (pixel rows grow downwards).
    std::vector<float> columnTangent;
    std::vector<float> rowTangent;

    // Tiles for a target and projection; slicing starts as [nearPlane, farPlane] until
    // setSlicing() gives the measured range.
    static ClusterGrid make(uint32_t tileSize, uint32_t slices, uint32_t width, uint32_t height,
                            float projectionScaleX, float projectionScaleY, float nearPlane,
                            float farPlane);
    // The preferred tile size, doubled until a buffer of `bytesPerCluster` per cluster fits in
    // `maxBufferBytes` (a device's maxStorageBufferRange): at 16 px and 64 slices, the cluster
    // bounds of a 3840x2160 frame take 248 MB, past the 128 MiB many drivers bind.
    static uint32_t tileSizeFitting(uint32_t preferredTileSize, uint32_t slices, uint32_t width,
                                    uint32_t height, uint64_t bytesPerCluster,
                                    uint64_t maxBufferBytes);
    void setSlicing(float sliceNearDepth, float sliceLogRatio) {
        sliceNear = sliceNearDepth;
        logRatio = sliceLogRatio;
    }

    uint32_t clusterCount() const { return tilesX * tilesY * slices; }
    uint32_t tileCount() const { return tilesX * tilesY; }
    uint32_t clusterIndex(uint32_t x, uint32_t y, uint32_t slice) const {
        return (slice * tilesY + y) * tilesX + x;
    }
    // Near edge of a slice (0 for slice 0, which reaches the camera).
    float sliceDepth(uint32_t slice) const {
        return slice == 0 ? 0.0f : sliceNear * std::exp(logRatio * float(slice));
    }
    uint32_t sliceOf(float depth) const {
        if (!(depth > sliceNear)) return 0;
        float k = std::floor(std::log(depth / sliceNear) / logRatio);
        return k >= float(slices - 1) ? slices - 1 : uint32_t(k);
    }
};

}  // namespace candela::render
