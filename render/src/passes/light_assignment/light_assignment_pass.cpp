#include "passes/light_assignment/light_assignment_pass.h"

#include <algorithm>
#include <cstring>

#include "candela/render/gpu_context.h"
#include "clustered/gpu_cluster_params.h"
#include "common/specialization_ids.h"
#include "passes/light_assignment/light_assignment_bindings.h"
#include "shaders/allocate_lists.comp.spv.h"
#include "shaders/assign_lights.comp.spv.h"
#include "shaders/sort_lists.comp.spv.h"

namespace candela::render {

namespace {

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

uint32_t groups(uint32_t invocations) {
    return (invocations + 63) / 64;
}

}  // namespace

LightAssignmentPass::LightAssignmentPass(GpuContext& context) : context_(context) {
    const DescriptorBinding assignBindings[] = {
        {LIGHT_BUFFER_BINDING, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
        {ASSIGN_BINDING_OCCUPANCY, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
        {ASSIGN_BINDING_CLUSTER_BOUNDS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
         VK_SHADER_STAGE_COMPUTE_BIT},
        {ASSIGN_BINDING_DEPTH_RANGE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
         VK_SHADER_STAGE_COMPUTE_BIT},
        {ASSIGN_BINDING_CLUSTER_COUNTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
         VK_SHADER_STAGE_COMPUTE_BIT},
        {ASSIGN_BINDING_CLUSTER_RANGES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
         VK_SHADER_STAGE_COMPUTE_BIT},
        {ASSIGN_BINDING_LIGHT_INDICES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
         VK_SHADER_STAGE_COMPUTE_BIT},
    };
    for (bool write : {false, true}) {
        SpecializationConstants constants;
        constants.set(SPEC_ASSIGN_WRITE_PASS, write);
        (write ? writePipeline_ : countPipeline_) = Pipeline::compute(
            context, assign_lights_comp_spv, assignBindings, sizeof(AssignPush), &constants);
    }
    const DescriptorBinding allocateBindings[] = {
        {ALLOCATE_BINDING_CLUSTER_COUNTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
         VK_SHADER_STAGE_COMPUTE_BIT},
        {ALLOCATE_BINDING_CLUSTER_RANGES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
         VK_SHADER_STAGE_COMPUTE_BIT},
        {ALLOCATE_BINDING_LIST_USAGE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
         VK_SHADER_STAGE_COMPUTE_BIT},
        {ALLOCATE_BINDING_OCCUPANCY, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
         VK_SHADER_STAGE_COMPUTE_BIT},
        {ALLOCATE_BINDING_PREVIOUS_OCCUPANCY, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
         VK_SHADER_STAGE_COMPUTE_BIT},
    };
    allocatePipeline_ =
        Pipeline::compute(context, allocate_lists_comp_spv, allocateBindings, sizeof(AllocatePush));
    const DescriptorBinding sortBindings[] = {
        {SORT_BINDING_CLUSTER_RANGES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
         VK_SHADER_STAGE_COMPUTE_BIT},
        {SORT_BINDING_LIGHT_INDICES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
         VK_SHADER_STAGE_COMPUTE_BIT},
        {SORT_BINDING_CLUSTER_COUNTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
         VK_SHADER_STAGE_COMPUTE_BIT},
        {SORT_BINDING_OCCUPANCY, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
    };
    sortPipeline_ = Pipeline::compute(context, sort_lists_comp_spv, sortBindings, sizeof(SortPush));
    usage_ =
        GpuBuffer(context, 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryLocation::HostVisible);
    *static_cast<uint32_t*>(usage_.mapped()) = 0;
}

uint32_t LightAssignmentPass::requestedEntries() const {
    return *static_cast<const uint32_t*>(usage_.mapped());
}

void LightAssignmentPass::prepare(const Inputs& in) {
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
}

namespace {
struct AssignDescriptors {
    VkDescriptorBufferInfo lights, masks, bounds, range, counts, ranges, indices, usage, previous;
};
AssignDescriptors describe(const LightAssignmentPass::Inputs& in, const GpuBuffer& counts,
                           const GpuBuffer& usage, const GpuBuffer& previous) {
    return {{in.lights->handle(), 0, VK_WHOLE_SIZE},
            {in.tileMasks->handle(), 0, VK_WHOLE_SIZE},
            {in.clusterBounds->handle(), 0, VK_WHOLE_SIZE},
            {in.depthRange->handle(), 0, VK_WHOLE_SIZE},
            {counts.handle(), 0, VK_WHOLE_SIZE},
            {in.clusterRanges->handle(), 0, VK_WHOLE_SIZE},
            {in.lightIndices->handle(), 0, VK_WHOLE_SIZE},
            {usage.handle(), 0, VK_WHOLE_SIZE},
            {previous.handle(), 0, VK_WHOLE_SIZE}};
}
}  // namespace

// The count and write passes run the same per-light walk (assign_lights.comp), with the same
// bindings; a specialization constant picks counting or writing.
void LightAssignmentPass::recordWalk(VkCommandBuffer cmd, const Inputs& in,
                                     const Pipeline& pipeline) const {
    const AssignDescriptors d = describe(in, clusterCounts_, usage_, previousMasks_);
    const VkWriteDescriptorSet writes[] = {
        storageBufferWrite(LIGHT_BUFFER_BINDING, &d.lights),
        storageBufferWrite(ASSIGN_BINDING_OCCUPANCY, &d.masks),
        storageBufferWrite(ASSIGN_BINDING_CLUSTER_BOUNDS, &d.bounds),
        storageBufferWrite(ASSIGN_BINDING_DEPTH_RANGE, &d.range),
        storageBufferWrite(ASSIGN_BINDING_CLUSTER_COUNTS, &d.counts),
        storageBufferWrite(ASSIGN_BINDING_CLUSTER_RANGES, &d.ranges),
        storageBufferWrite(ASSIGN_BINDING_LIGHT_INDICES, &d.indices)};
    AssignPush assign{in.view,
                      toGpu(*in.grid),
                      {in.width, in.height},
                      {in.projectionScale.x, in.projectionScale.y},
                      in.lightCount,
                      in.lightCapacity};
    pipeline.bind(cmd);
    pipeline.pushDescriptors(cmd, writes);
    pipeline.pushConstants(cmd, &assign, sizeof(assign));
    vkCmdDispatch(cmd, std::max(groups(in.lightCount), 1u), 1, 1);
}

void LightAssignmentPass::recordCount(VkCommandBuffer cmd, const Inputs& in) const {
    recordWalk(cmd, in, countPipeline_);
}

void LightAssignmentPass::recordAllocate(VkCommandBuffer cmd, const Inputs& in) const {
    const AssignDescriptors d = describe(in, clusterCounts_, usage_, previousMasks_);
    const VkWriteDescriptorSet writes[] = {
        storageBufferWrite(ALLOCATE_BINDING_CLUSTER_COUNTS, &d.counts),
        storageBufferWrite(ALLOCATE_BINDING_CLUSTER_RANGES, &d.ranges),
        storageBufferWrite(ALLOCATE_BINDING_LIST_USAGE, &d.usage),
        storageBufferWrite(ALLOCATE_BINDING_OCCUPANCY, &d.masks),
        storageBufferWrite(ALLOCATE_BINDING_PREVIOUS_OCCUPANCY, &d.previous)};
    AllocatePush allocate{in.grid->tileCount(), in.lightIndexCapacity};
    allocatePipeline_.bind(cmd);
    allocatePipeline_.pushDescriptors(cmd, writes);
    allocatePipeline_.pushConstants(cmd, &allocate, sizeof(allocate));
    vkCmdDispatch(cmd, groups(in.grid->tileCount()), 1, 1);
}

void LightAssignmentPass::recordWrite(VkCommandBuffer cmd, const Inputs& in) const {
    recordWalk(cmd, in, writePipeline_);
}

void LightAssignmentPass::recordSort(VkCommandBuffer cmd, const Inputs& in) const {
    const AssignDescriptors d = describe(in, clusterCounts_, usage_, previousMasks_);
    const VkWriteDescriptorSet writes[] = {
        storageBufferWrite(SORT_BINDING_CLUSTER_RANGES, &d.ranges),
        storageBufferWrite(SORT_BINDING_LIGHT_INDICES, &d.indices),
        storageBufferWrite(SORT_BINDING_CLUSTER_COUNTS, &d.counts),
        storageBufferWrite(SORT_BINDING_OCCUPANCY, &d.masks)};
    SortPush sort{in.grid->tileCount()};
    sortPipeline_.bind(cmd);
    sortPipeline_.pushDescriptors(cmd, writes);
    sortPipeline_.pushConstants(cmd, &sort, sizeof(sort));
    vkCmdDispatch(cmd, in.grid->tileCount(), 1, 1);
}

}  // namespace candela::render
