#include "passes/taa/taa_pass.h"

#include "candela/render/gpu_image.h"
#include "passes/taa/taa_bindings.h"
#include "shaders/taa.comp.spv.h"

namespace candela::render {

namespace {

struct TaaPush {
    float exposure;
    float minimumBlend;
    uint32_t historyValid;
    float sharpness;
};

float halton(uint32_t index, uint32_t base) {
    float result = 0.0f;
    float fraction = 1.0f;
    while (index > 0) {
        fraction /= float(base);
        result += fraction * float(index % base);
        index /= base;
    }
    return result;
}

}  // namespace

TaaPass::TaaPass(GpuContext& context)
    : nearest_(context, SamplerDesc{VK_FILTER_NEAREST}), linear_(context, SamplerDesc{}) {
    const DescriptorBinding bindings[] = {
        {TAA_BINDING_CURRENT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_SHADER_STAGE_COMPUTE_BIT},
        {TAA_BINDING_MOTION, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
         VK_SHADER_STAGE_COMPUTE_BIT},
        {TAA_BINDING_HISTORY, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
         VK_SHADER_STAGE_COMPUTE_BIT},
        {TAA_BINDING_RESOLVED, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_SHADER_STAGE_COMPUTE_BIT},
    };
    pipeline_ = Pipeline::compute(context, taa_comp_spv, bindings, sizeof(TaaPush));
}

// Index 1..16: index 0 of Halton is (0, 0) for every base, a corner, not a sample.
float TaaPass::jitterX(uint32_t frame) {
    return halton(frame % kJitterPhases + 1, 2) - 0.5f;
}

float TaaPass::jitterY(uint32_t frame) {
    return halton(frame % kJitterPhases + 1, 3) - 0.5f;
}

void TaaPass::recordResolve(VkCommandBuffer cmd, const ImageRef& current, const ImageRef& motion,
                            const ImageRef& history, const ImageRef& resolved,
                            const Settings& settings) const {
    VkDescriptorImageInfo currentInfo{VK_NULL_HANDLE, current.view(), VK_IMAGE_LAYOUT_GENERAL};
    VkDescriptorImageInfo motionInfo{nearest_.handle(), motion.view(),
                                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorImageInfo historyInfo{linear_.handle(), history.view(),
                                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorImageInfo resolvedInfo{VK_NULL_HANDLE, resolved.view(), VK_IMAGE_LAYOUT_GENERAL};
    const VkWriteDescriptorSet writes[] = {storageImageWrite(TAA_BINDING_CURRENT, &currentInfo),
                                           sampledImageWrite(TAA_BINDING_MOTION, &motionInfo),
                                           sampledImageWrite(TAA_BINDING_HISTORY, &historyInfo),
                                           storageImageWrite(TAA_BINDING_RESOLVED, &resolvedInfo)};
    TaaPush push{settings.exposure, settings.minimumBlend, settings.historyValid ? 1u : 0u,
                 settings.sharpness};
    pipeline_.bind(cmd);
    pipeline_.pushDescriptors(cmd, writes);
    pipeline_.pushConstants(cmd, &push, sizeof(push));
    vkCmdDispatch(cmd, (current.desc().width + 7) / 8, (current.desc().height + 7) / 8, 1);
}

}  // namespace candela::render
