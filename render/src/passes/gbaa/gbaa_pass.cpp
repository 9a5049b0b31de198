#include "passes/gbaa/gbaa_pass.h"

#include "candela/render/gpu_image.h"
#include "passes/gbaa/gbaa_bindings.h"
#include "shaders/gbaa.comp.spv.h"

namespace candela::render {

GbaaPass::GbaaPass(GpuContext& context) : nearest_(context, SamplerDesc{VK_FILTER_NEAREST}) {
    const DescriptorBinding bindings[] = {
        {GBAA_BINDING_HDR, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_SHADER_STAGE_COMPUTE_BIT},
        {GBAA_BINDING_EDGES, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
         VK_SHADER_STAGE_COMPUTE_BIT},
        {GBAA_BINDING_RESOLVED, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_SHADER_STAGE_COMPUTE_BIT},
    };
    pipeline_ = Pipeline::compute(context, gbaa_comp_spv, bindings, 0);
}

void GbaaPass::recordResolve(VkCommandBuffer cmd, const ImageRef& hdr, const ImageRef& edges,
                             const ImageRef& resolved) const {
    VkDescriptorImageInfo hdrInfo{VK_NULL_HANDLE, hdr.view(), VK_IMAGE_LAYOUT_GENERAL};
    VkDescriptorImageInfo edgesInfo{nearest_.handle(), edges.view(),
                                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorImageInfo resolvedInfo{VK_NULL_HANDLE, resolved.view(), VK_IMAGE_LAYOUT_GENERAL};
    const VkWriteDescriptorSet writes[] = {storageImageWrite(GBAA_BINDING_HDR, &hdrInfo),
                                           sampledImageWrite(GBAA_BINDING_EDGES, &edgesInfo),
                                           storageImageWrite(GBAA_BINDING_RESOLVED, &resolvedInfo)};
    pipeline_.bind(cmd);
    pipeline_.pushDescriptors(cmd, writes);
    vkCmdDispatch(cmd, (hdr.desc().width + 7) / 8, (hdr.desc().height + 7) / 8, 1);
}

}  // namespace candela::render
