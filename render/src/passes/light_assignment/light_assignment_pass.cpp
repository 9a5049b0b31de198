#include "passes/light_assignment/light_assignment_pass.h"

#include <algorithm>
#include <cstring>

#include "candela/render/gpu_context.h"
#include "clustered/gpu_cluster_params.h"
#include "shaders/allocate_lists.comp.spv.h"
#include "shaders/assign_lights.comp.spv.h"
#include "shaders/sort_lists.comp.spv.h"
#include "vk/memory_barrier.h"

namespace candela::render {

namespace {

constexpr uint32_t kWritePassConstant = 0;  // assign_lights.comp

struct AssignPush {
    glm::mat4 view;
    GpuClusterParams grid;
    uint32_t size[2];
    float projectionScale[2];
    uint32_t lightCount;
    uint32_t lightCapacity;
};
static_assert(sizeof(AssignPush) <= 128, "push constants beyond the guaranteed 128 bytes");

struct AllocatePush {
    uint32_t tileCount;
    uint32_t capacity;
};

struct SortPush {
    uint32_t tileCount;
};

void computeBarrier(VkCommandBuffer cmd) {
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                  VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
}

uint32_t groups(uint32_t invocations) {
    return (invocations + 63) / 64;
}

}  // namespace

LightAssignmentPass::LightAssignmentPass(GpuContext& context) : context_(context) {
    const DescriptorBinding assignBindings[] = {
        {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
        {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
        {3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
        {4, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
        {5, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
        {6, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
        {7, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
    };
    for (bool write : {false, true}) {
        SpecializationConstants constants;
        constants.set(kWritePassConstant, write);
        (write ? writePipeline_ : countPipeline_) = Pipeline::compute(
            context, assign_lights_comp_spv, assignBindings, sizeof(AssignPush), &constants);
    }
    const DescriptorBinding allocateBindings[] = {
        {0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
        {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
        {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
        {3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
        {4, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
    };
    allocatePipeline_ =
        Pipeline::compute(context, allocate_lists_comp_spv, allocateBindings, sizeof(AllocatePush));
    const DescriptorBinding sortBindings[] = {
        {0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
        {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
        {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
        {3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
    };
    sortPipeline_ = Pipeline::compute(context, sort_lists_comp_spv, sortBindings, sizeof(SortPush));
    usage_ =
        GpuBuffer(context, 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryLocation::HostVisible);
    *static_cast<uint32_t*>(usage_.mapped()) = 0;
}

uint32_t LightAssignmentPass::requestedEntries() const {
    return *static_cast<const uint32_t*>(usage_.mapped());
}

void LightAssignmentPass::record(VkCommandBuffer cmd, const Inputs& in) {
    const ClusterGrid& grid = *in.grid;
    // Cluster counts and ranges persist between frames: the sort pass leaves every count at
    // zero and the allocate pass keeps every range the lighting pass can read current. Start
    // from zeros whenever the grid's layout or the range buffer changed.
    const VkDeviceSize countBytes = VkDeviceSize(grid.clusterCount()) * 4;
    const VkDeviceSize maskBytes = VkDeviceSize(grid.tileCount()) * 8;
    const bool layoutChanged = grid.tilesX != tilesX_ || grid.tilesY != tilesY_ ||
                               grid.slices != slices_ || in.clusterRanges->handle() != ranges_;
    if (!clusterCounts_.handle() || clusterCounts_.size() < countBytes) {
        clusterCounts_ = GpuBuffer(context_, std::max<VkDeviceSize>(countBytes, 16),
                                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryLocation::HostVisible);
        std::memset(clusterCounts_.mapped(), 0, clusterCounts_.size());
    }
    if (!previousMasks_.handle() || previousMasks_.size() < maskBytes) {
        previousMasks_ = GpuBuffer(context_, std::max<VkDeviceSize>(maskBytes, 16),
                                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryLocation::HostVisible);
        std::memset(previousMasks_.mapped(), 0, previousMasks_.size());
    }
    if (layoutChanged) {
        std::memset(previousMasks_.mapped(), 0, previousMasks_.size());
        std::memset(in.clusterRanges->mapped(), 0, VkDeviceSize(grid.clusterCount()) * 8);
        tilesX_ = grid.tilesX;
        tilesY_ = grid.tilesY;
        slices_ = grid.slices;
        ranges_ = in.clusterRanges->handle();
    }
    // The previous frame has completed (the renderer read its usage already): written by the
    // host, as a fill command costs more than the whole allocate pass on lavapipe.
    *static_cast<uint32_t*>(usage_.mapped()) = in.directionalCount;

    VkDescriptorBufferInfo lights{in.lights->handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo masks{in.tileMasks->handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo bounds{in.clusterBounds->handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo range{in.depthRange->handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo counts{clusterCounts_.handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo ranges{in.clusterRanges->handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo indices{in.lightIndices->handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo usage{usage_.handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo previous{previousMasks_.handle(), 0, VK_WHOLE_SIZE};
    const VkWriteDescriptorSet assignWrites[] = {
        storageBufferWrite(1, &lights), storageBufferWrite(2, &masks),
        storageBufferWrite(3, &bounds), storageBufferWrite(4, &range),
        storageBufferWrite(5, &counts), storageBufferWrite(6, &ranges),
        storageBufferWrite(7, &indices)};
    AssignPush assign{in.view,
                      toGpu(grid),
                      {in.width, in.height},
                      {in.projectionScale.x, in.projectionScale.y},
                      in.lightCount,
                      in.lightCapacity};

    countPipeline_.bind(cmd);
    countPipeline_.pushDescriptors(cmd, assignWrites);
    countPipeline_.pushConstants(cmd, &assign, sizeof(assign));
    vkCmdDispatch(cmd, std::max(groups(in.lightCount), 1u), 1, 1);
    computeBarrier(cmd);

    const VkWriteDescriptorSet allocateWrites[] = {
        storageBufferWrite(0, &counts), storageBufferWrite(1, &ranges),
        storageBufferWrite(2, &usage), storageBufferWrite(3, &masks),
        storageBufferWrite(4, &previous)};
    AllocatePush allocate{grid.tileCount(), in.lightIndexCapacity};
    allocatePipeline_.bind(cmd);
    allocatePipeline_.pushDescriptors(cmd, allocateWrites);
    allocatePipeline_.pushConstants(cmd, &allocate, sizeof(allocate));
    vkCmdDispatch(cmd, groups(grid.tileCount()), 1, 1);
    computeBarrier(cmd);

    writePipeline_.bind(cmd);
    writePipeline_.pushDescriptors(cmd, assignWrites);
    writePipeline_.pushConstants(cmd, &assign, sizeof(assign));
    vkCmdDispatch(cmd, std::max(groups(in.lightCount), 1u), 1, 1);
    computeBarrier(cmd);

    const VkWriteDescriptorSet sortWrites[] = {
        storageBufferWrite(0, &ranges), storageBufferWrite(1, &indices),
        storageBufferWrite(2, &counts), storageBufferWrite(3, &masks)};
    SortPush sort{grid.tileCount()};
    sortPipeline_.bind(cmd);
    sortPipeline_.pushDescriptors(cmd, sortWrites);
    sortPipeline_.pushConstants(cmd, &sort, sizeof(sort));
    vkCmdDispatch(cmd, grid.tileCount(), 1, 1);
    computeBarrier(cmd);
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
}

}  // namespace candela::render
