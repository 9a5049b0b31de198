#pragma once
// Measures what the depth buffer holds, for light assignment: the nearest and farthest
// geometry (where the cluster slices go), which slices of each tile are occupied (64-bit mask
// per tile), and a view-space box around each occupied cluster's pixels.
#include <glm/glm.hpp>

#include "candela/render/pipeline.h"
#include "clustered/cluster_grid.h"
#include "frame_graph/graph_resources.h"

namespace candela::render {

class GpuBuffer;
class GpuContext;

class DepthOccupancyPass {
public:
    explicit DepthOccupancyPass(GpuContext& context);
    ~DepthOccupancyPass();
    DepthOccupancyPass(const DepthOccupancyPass&) = delete;
    DepthOccupancyPass& operator=(const DepthOccupancyPass&) = delete;

    struct Outputs {
        const GpuBuffer* tileMasks;      // grid.tileCount() uvec2
        const GpuBuffer* clusterBounds;  // grid.clusterCount() x CLUSTER_BOUNDS_FLOATS (occupied)
        const GpuBuffer* depthRange;     // 4 uints: min, max depth bits; sliceNear, logRatio
    };
    // Three frame-graph passes, in this order. clearRange: depthRange (TransferDst).
    // measureRange: depth (Sampled), depthRange (StorageReadWrite). markOccupancy: depth
    // (Sampled), depthRange (StorageReadWrite: the slicing it chose lands in [2..3]),
    // tileMasks and clusterBounds (StorageWrite). Uses the grid's tiles and slice count.
    void recordClearRange(VkCommandBuffer cmd, const GpuBuffer& depthRange) const;
    void recordMeasureRange(VkCommandBuffer cmd, const ImageRef& depth, const ClusterGrid& grid,
                            const GpuBuffer& depthRange) const;
    void recordMarkOccupancy(VkCommandBuffer cmd, const ImageRef& depth, const ClusterGrid& grid,
                             const glm::vec2& projectionScale, const Outputs& outputs) const;

private:
    GpuContext& context_;
    Pipeline rangePipeline_;
    Pipeline occupancyPipeline_;
    VkSampler sampler_ = VK_NULL_HANDLE;
};

}  // namespace candela::render
