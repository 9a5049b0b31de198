#include "passes/depth_occupancy/depth_occupancy_pass.h"

#include "candela/render/gpu_buffer.h"
#include "candela/render/gpu_context.h"
#include "candela/render/gpu_image.h"
#include "clustered/gpu_cluster_params.h"
#include "passes/depth_occupancy/depth_occupancy_bindings.h"
#include "shaders/depth_occupancy.comp.spv.h"
#include "shaders/depth_range.comp.spv.h"
#include "vk/vk_check.h"

namespace candela::render {

namespace {

struct RangePush {
    uint32_t width;
    uint32_t height;
    float projectionNear;
};

struct OccupancyPush {
    GpuClusterParams grid;
    uint32_t width;
    uint32_t height;
    float projectionScale[2];
};

}  // namespace

DepthOccupancyPass::DepthOccupancyPass(GpuContext& context) : context_(context) {
    const DescriptorBinding rangeBindings[] = {
        {DEPTH_RANGE_BINDING_DEPTH, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
         VK_SHADER_STAGE_COMPUTE_BIT},
        {DEPTH_RANGE_BINDING_RANGE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
    };
    rangePipeline_ =
        Pipeline::compute(context, depth_range_comp_spv, rangeBindings, sizeof(RangePush));
    const DescriptorBinding occupancyBindings[] = {
        {OCCUPANCY_BINDING_DEPTH, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
         VK_SHADER_STAGE_COMPUTE_BIT},
        {OCCUPANCY_BINDING_TILE_MASKS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
         VK_SHADER_STAGE_COMPUTE_BIT},
        {OCCUPANCY_BINDING_CLUSTER_BOUNDS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
         VK_SHADER_STAGE_COMPUTE_BIT},
        {OCCUPANCY_BINDING_DEPTH_RANGE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
         VK_SHADER_STAGE_COMPUTE_BIT},
    };
    occupancyPipeline_ = Pipeline::compute(context, depth_occupancy_comp_spv, occupancyBindings,
                                           sizeof(OccupancyPush));
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = VK_FILTER_NEAREST;
    info.minFilter = VK_FILTER_NEAREST;
    CANDELA_VK_CHECK(vkCreateSampler(context.device(), &info, nullptr, &sampler_));
}

DepthOccupancyPass::~DepthOccupancyPass() {
    vkDestroySampler(context_.device(), sampler_, nullptr);
}

void DepthOccupancyPass::recordClearRange(VkCommandBuffer cmd, const GpuBuffer& depthRange) const {
    // min starts at the largest ordered value, max at the smallest.
    vkCmdFillBuffer(cmd, depthRange.handle(), 0, 4, 0xffffffffu);
    vkCmdFillBuffer(cmd, depthRange.handle(), 4, 4, 0u);
}

void DepthOccupancyPass::recordMeasureRange(VkCommandBuffer cmd, const ImageRef& depth,
                                            const ClusterGrid& grid,
                                            const GpuBuffer& depthRange) const {
    const uint32_t width = depth.desc().width;
    const uint32_t height = depth.desc().height;
    VkDescriptorImageInfo depthInfo{sampler_, depth.view(),
                                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorBufferInfo rangeInfo{depthRange.handle(), 0, VK_WHOLE_SIZE};
    const VkWriteDescriptorSet rangeWrites[] = {
        sampledImageWrite(DEPTH_RANGE_BINDING_DEPTH, &depthInfo),
        storageBufferWrite(DEPTH_RANGE_BINDING_RANGE, &rangeInfo)};
    RangePush rangePush{width, height, grid.nearPlane};
    rangePipeline_.bind(cmd);
    rangePipeline_.pushDescriptors(cmd, rangeWrites);
    rangePipeline_.pushConstants(cmd, &rangePush, sizeof(rangePush));
    // depth_range.comp: an invocation per 8x8 block, 8 invocations a workgroup.
    const uint32_t blocks = ((width + 7) / 8) * ((height + 7) / 8);
    vkCmdDispatch(cmd, (blocks + 7) / 8, 1, 1);
}

void DepthOccupancyPass::recordMarkOccupancy(VkCommandBuffer cmd, const ImageRef& depth,
                                             const ClusterGrid& grid,
                                             const glm::vec2& projectionScale,
                                             const Outputs& outputs) const {
    const uint32_t width = depth.desc().width;
    const uint32_t height = depth.desc().height;
    VkDescriptorImageInfo depthInfo{sampler_, depth.view(),
                                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorBufferInfo rangeInfo{outputs.depthRange->handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo maskInfo{outputs.tileMasks->handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorBufferInfo boundsInfo{outputs.clusterBounds->handle(), 0, VK_WHOLE_SIZE};
    const VkWriteDescriptorSet writes[] = {
        sampledImageWrite(OCCUPANCY_BINDING_DEPTH, &depthInfo),
        storageBufferWrite(OCCUPANCY_BINDING_TILE_MASKS, &maskInfo),
        storageBufferWrite(OCCUPANCY_BINDING_CLUSTER_BOUNDS, &boundsInfo),
        storageBufferWrite(OCCUPANCY_BINDING_DEPTH_RANGE, &rangeInfo)};
    OccupancyPush push{toGpu(grid), width, height, {projectionScale.x, projectionScale.y}};
    occupancyPipeline_.bind(cmd);
    occupancyPipeline_.pushDescriptors(cmd, writes);
    occupancyPipeline_.pushConstants(cmd, &push, sizeof(push));
    // depth_occupancy.comp: a workgroup takes 8 tiles, an invocation a quarter of one.
    const uint32_t tiles = grid.tilesX * grid.tilesY;
    vkCmdDispatch(cmd, (tiles + 7) / 8, 1, 1);
}

}  // namespace candela::render
