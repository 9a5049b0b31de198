#pragma once
// Push-constant mirror of ClusterGridParams in render/shaders/common/clusters.glsl.
#include <cstdint>

#include "clustered/cluster_grid.h"

namespace candela::render {

struct GpuClusterParams {
    uint32_t tileSize;
    uint32_t tilesX;
    uint32_t tilesY;
    uint32_t slices;
    float projectionNear;
    float sliceNear;
    float logRatio;
    uint32_t pad;
};

inline GpuClusterParams toGpu(const ClusterGrid& g) {
    return {g.tileSize, g.tilesX, g.tilesY, g.slices, g.nearPlane, g.sliceNear, g.logRatio, 0};
}

}  // namespace candela::render
