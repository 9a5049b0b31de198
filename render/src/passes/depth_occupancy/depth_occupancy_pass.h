#pragma once
// Marks, per screen tile, the depth slices that hold geometry (64-bit mask per tile).
#include "candela/render/pipeline.h"
#include "clustered/cluster_grid.h"

namespace candela::render {

class GpuBuffer;
class GpuContext;
class GpuImage;

class DepthOccupancyPass {
public:
    explicit DepthOccupancyPass(GpuContext& context);
    ~DepthOccupancyPass();
    DepthOccupancyPass(const DepthOccupancyPass&) = delete;
    DepthOccupancyPass& operator=(const DepthOccupancyPass&) = delete;

    // depth must be SHADER_READ_ONLY; masks receives grid.tileCount() uvec2 values.
    void record(VkCommandBuffer cmd, const GpuImage& depth, const ClusterGrid& grid,
                const GpuBuffer& masks) const;

private:
    GpuContext& context_;
    Pipeline pipeline_;
    VkSampler sampler_ = VK_NULL_HANDLE;
};

}  // namespace candela::render
