#include "passes/tonemap/tonemap_pass.h"

#include "candela/render/gpu_image.h"
#include "passes/tonemap/tonemap_bindings.h"
#include "shaders/tonemap.comp.spv.h"

namespace candela::render {

TonemapPass::TonemapPass(GpuContext& context) {
    const DescriptorBinding bindings[] = {
        {TONEMAP_BINDING_HDR, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_SHADER_STAGE_COMPUTE_BIT},
        {TONEMAP_BINDING_LDR, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_SHADER_STAGE_COMPUTE_BIT},
    };
    pipeline_ = Pipeline::compute(context, tonemap_comp_spv, bindings, sizeof(float));
}

void TonemapPass::record(VkCommandBuffer cmd, const ImageRef& hdr, const ImageRef& ldr,
                         float exposure) const {
    VkDescriptorImageInfo hdrInfo{VK_NULL_HANDLE, hdr.view(), VK_IMAGE_LAYOUT_GENERAL};
    VkDescriptorImageInfo ldrInfo{VK_NULL_HANDLE, ldr.view(), VK_IMAGE_LAYOUT_GENERAL};
    const VkWriteDescriptorSet writes[] = {storageImageWrite(TONEMAP_BINDING_HDR, &hdrInfo),
                                           storageImageWrite(TONEMAP_BINDING_LDR, &ldrInfo)};
    pipeline_.bind(cmd);
    pipeline_.pushDescriptors(cmd, writes);
    pipeline_.pushConstants(cmd, &exposure, sizeof(exposure));
    vkCmdDispatch(cmd, (hdr.desc().width + 7) / 8, (hdr.desc().height + 7) / 8, 1);
}

}  // namespace candela::render
