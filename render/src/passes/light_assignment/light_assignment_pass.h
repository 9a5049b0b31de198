#pragma once
// Light assignment in compute shaders: the same per-cluster lists as the CPU path
// (clustered/light_assignment.h: offset + count per cluster, directional lights first, every
// list in ascending light order), built on the device right after the depth occupancy pass,
// so the frame needs no mid-frame wait. Passes: count (per light), allocate (per tile), write
// (per light), sort (per tile). The index buffer has a fixed capacity per frame; clusters
// that do not fit are marked overflowed (the lighting pass then evaluates every light there)
// and requestedEntries() tells the renderer how large to grow it.
#include <glm/glm.hpp>

#include "candela/render/gpu_buffer.h"
#include "candela/render/pipeline.h"
#include "clustered/cluster_grid.h"

namespace candela::render {

class GpuContext;

class LightAssignmentPass {
public:
    explicit LightAssignmentPass(GpuContext& context);

    struct Inputs {
        const GpuBuffer* lights;  // GpuLightBuffer's structure-of-arrays streams
        uint32_t lightCount;
        uint32_t lightCapacity;
        glm::mat4 view;
        const ClusterGrid* grid;  // tiles and slice count; slicing comes from depthRange
        uint32_t width;
        uint32_t height;
        glm::vec2 projectionScale;   // projection[0][0], projection[1][1]
        const GpuBuffer* tileMasks;  // DepthOccupancyPass outputs
        const GpuBuffer* clusterBounds;
        const GpuBuffer* depthRange;
        const GpuBuffer* clusterRanges;  // out: uvec2 per cluster (host-visible)
        const GpuBuffer* lightIndices;   // out: directional indices already in [0, count)
        uint32_t lightIndexCapacity;     // entries lightIndices holds
        uint32_t directionalCount;
    };
    // Host side, before the frame is submitted: sizes and resets the persistent buffers.
    void prepare(const Inputs& inputs);
    // Four frame-graph passes, in this order, all compute. Each reads lights, tileMasks,
    // clusterBounds and depthRange (StorageRead) where its shader binds them and updates
    // (StorageReadWrite) what it writes: count -> clusterCounts; allocate -> clusterCounts,
    // clusterRanges, usage, previousMasks; write -> clusterCounts, lightIndices; sort ->
    // clusterRanges, lightIndices, clusterCounts. usage is read by the host after the frame.
    void recordCount(VkCommandBuffer cmd, const Inputs& inputs) const;
    void recordAllocate(VkCommandBuffer cmd, const Inputs& inputs) const;
    void recordWrite(VkCommandBuffer cmd, const Inputs& inputs) const;
    void recordSort(VkCommandBuffer cmd, const Inputs& inputs) const;
    const GpuBuffer& clusterCounts() const { return clusterCounts_; }
    const GpuBuffer& usage() const { return usage_; }
    const GpuBuffer& previousMasks() const { return previousMasks_; }

    // Index entries the last completed frame asked for (directional lights included); more
    // than its capacity means some clusters overflowed.
    uint32_t requestedEntries() const;

private:
    void recordWalk(VkCommandBuffer cmd, const Inputs& inputs, const Pipeline& pipeline) const;

    GpuContext& context_;
    Pipeline countPipeline_;
    Pipeline writePipeline_;
    Pipeline allocatePipeline_;
    Pipeline sortPipeline_;
    GpuBuffer clusterCounts_;  // per cluster: count, then the write cursor; zero between frames
    GpuBuffer usage_;          // entries requested (host-visible)
    GpuBuffer previousMasks_;  // each tile's occupancy mask of the previous frame
    // The layout the persistent buffers hold; a change starts them from zeros.
    uint32_t tilesX_ = 0;
    uint32_t tilesY_ = 0;
    uint32_t slices_ = 0;
    VkBuffer ranges_ = VK_NULL_HANDLE;
};

}  // namespace candela::render
