#include "passes/fxaa/fxaa_pass.h"

#include "candela/render/gpu_image.h"
#include "passes/fxaa/fxaa_bindings.h"
#include "shaders/fxaa.comp.spv.h"

namespace candela::render {

FxaaPass::FxaaPass(GpuContext& context) : linear_(context, SamplerDesc{}) {
    const DescriptorBinding bindings[] = {
        {FXAA_BINDING_INPUT, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
         VK_SHADER_STAGE_COMPUTE_BIT},
        {FXAA_BINDING_OUTPUT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_SHADER_STAGE_COMPUTE_BIT},
    };
    pipeline_ = Pipeline::compute(context, fxaa_comp_spv, bindings, 0);
}

void FxaaPass::record(VkCommandBuffer cmd, const ImageRef& tonemapped, const ImageRef& ldr) const {
    VkDescriptorImageInfo inputInfo{linear_.handle(), tonemapped.view(),
                                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorImageInfo outputInfo{VK_NULL_HANDLE, ldr.view(), VK_IMAGE_LAYOUT_GENERAL};
    const VkWriteDescriptorSet writes[] = {sampledImageWrite(FXAA_BINDING_INPUT, &inputInfo),
                                           storageImageWrite(FXAA_BINDING_OUTPUT, &outputInfo)};
    pipeline_.bind(cmd);
    pipeline_.pushDescriptors(cmd, writes);
    vkCmdDispatch(cmd, (ldr.desc().width + 7) / 8, (ldr.desc().height + 7) / 8, 1);
}

}  // namespace candela::render
