#include "passes/upscale/upscale_pass.h"

#include "candela/render/gpu_image.h"
#include "passes/upscale/upscale_bindings.h"
#include "shaders/upscale.comp.spv.h"

namespace candela::render {

UpscalePass::UpscalePass(GpuContext& context) : linear_(context, SamplerDesc{}) {
    const DescriptorBinding bindings[] = {
        {UPSCALE_BINDING_INPUT, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
         VK_SHADER_STAGE_COMPUTE_BIT},
        {UPSCALE_BINDING_OUTPUT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_SHADER_STAGE_COMPUTE_BIT},
    };
    pipeline_ = Pipeline::compute(context, upscale_comp_spv, bindings, 0);
}

void UpscalePass::record(VkCommandBuffer cmd, const ImageRef& source,
                         const ImageRef& target) const {
    VkDescriptorImageInfo inputInfo{linear_.handle(), source.view(),
                                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorImageInfo outputInfo{VK_NULL_HANDLE, target.view(), VK_IMAGE_LAYOUT_GENERAL};
    const VkWriteDescriptorSet writes[] = {sampledImageWrite(UPSCALE_BINDING_INPUT, &inputInfo),
                                           storageImageWrite(UPSCALE_BINDING_OUTPUT, &outputInfo)};
    pipeline_.bind(cmd);
    pipeline_.pushDescriptors(cmd, writes);
    vkCmdDispatch(cmd, (target.desc().width + 7) / 8, (target.desc().height + 7) / 8, 1);
}

}  // namespace candela::render
