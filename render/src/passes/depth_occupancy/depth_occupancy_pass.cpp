#include "passes/depth_occupancy/depth_occupancy_pass.h"

#include "candela/render/gpu_buffer.h"
#include "candela/render/gpu_context.h"
#include "candela/render/gpu_image.h"
#include "clustered/gpu_cluster_params.h"
#include "shaders/depth_occupancy.comp.spv.h"
#include "vk/vk_check.h"

namespace candela::render {

namespace {
struct Push {
    GpuClusterParams grid;
    uint32_t width;
    uint32_t height;
};
}  // namespace

DepthOccupancyPass::DepthOccupancyPass(GpuContext& context) : context_(context) {
    const DescriptorBinding bindings[] = {
        {0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_COMPUTE_BIT},
        {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
    };
    pipeline_ = Pipeline::compute(context, depth_occupancy_comp_spv, bindings, sizeof(Push));
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = VK_FILTER_NEAREST;
    info.minFilter = VK_FILTER_NEAREST;
    CANDELA_VK_CHECK(vkCreateSampler(context.device(), &info, nullptr, &sampler_));
}

DepthOccupancyPass::~DepthOccupancyPass() {
    vkDestroySampler(context_.device(), sampler_, nullptr);
}

void DepthOccupancyPass::record(VkCommandBuffer cmd, const GpuImage& depth, const ClusterGrid& grid,
                                const GpuBuffer& masks) const {
    VkDescriptorImageInfo depthInfo{sampler_, depth.view(),
                                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorBufferInfo maskInfo{masks.handle(), 0, VK_WHOLE_SIZE};
    const VkWriteDescriptorSet writes[] = {sampledImageWrite(0, &depthInfo),
                                           storageBufferWrite(1, &maskInfo)};
    Push push{toGpu(grid), depth.desc().width, depth.desc().height};
    pipeline_.bind(cmd);
    pipeline_.pushDescriptors(cmd, writes);
    pipeline_.pushConstants(cmd, &push, sizeof(push));
    vkCmdDispatch(cmd, grid.tilesX, grid.tilesY, 1);
}

}  // namespace candela::render
