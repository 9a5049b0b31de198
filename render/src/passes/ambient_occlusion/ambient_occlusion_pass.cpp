#include "passes/ambient_occlusion/ambient_occlusion_pass.h"

#include "candela/render/gpu_context.h"
#include "candela/render/gpu_image.h"
#include "passes/ambient_occlusion/ambient_occlusion_bindings.h"
#include "shaders/ao_denoise.comp.spv.h"
#include "shaders/ao_reference.comp.spv.h"
#include "shaders/gtao.comp.spv.h"

namespace candela::render {

namespace {

// The push block of all three shaders.
struct Push {
    float radius;
    uint32_t slices;  // GTAO: slices; reference: rays
    uint32_t steps;
    float thickness;
};

constexpr VkShaderStageFlags kCompute = VK_SHADER_STAGE_COMPUTE_BIT;

uint32_t groups(uint32_t pixels) {
    return (pixels + 7) / 8;
}

}  // namespace

AmbientOcclusionPass::AmbientOcclusionPass(GpuContext& context)
    : pointSampler_(context, SamplerDesc{VK_FILTER_NEAREST}) {
    const DescriptorBinding gtao[] = {
        {CAMERA_BINDING, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kCompute},
        {AO_BINDING_DEPTH, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
        {AO_BINDING_NORMAL, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
        {AO_BINDING_OUTPUT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kCompute},
    };
    gtao_ = Pipeline::compute(context, gtao_comp_spv, gtao, sizeof(Push));
    const DescriptorBinding denoise[] = {
        {CAMERA_BINDING, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kCompute},
        {AO_BINDING_DEPTH, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
        {AO_BINDING_NORMAL, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
        {AO_BINDING_INPUT, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
        {AO_BINDING_SECOND_OUTPUT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kCompute},
    };
    denoise_ = Pipeline::compute(context, ao_denoise_comp_spv, denoise, 0);
    const DescriptorBinding reference[] = {
        {CAMERA_BINDING, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kCompute},
        {AO_BINDING_DEPTH, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
        {AO_BINDING_NORMAL, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
        {AO_BINDING_OUTPUT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kCompute},
        {AO_BINDING_SECOND_OUTPUT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kCompute},
    };
    reference_ = Pipeline::compute(context, ao_reference_comp_spv, reference, sizeof(Push));
}

ImageDesc AmbientOcclusionPass::occlusionDesc(uint32_t width, uint32_t height) {
    return {VK_FORMAT_R16G16B16A16_SFLOAT,
            width,
            height,
            1,
            false,
            VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT};
}

ImageDesc AmbientOcclusionPass::specularDesc(uint32_t width, uint32_t height) {
    return {VK_FORMAT_R16_SFLOAT,
            width,
            height,
            1,
            false,
            VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT};
}

void AmbientOcclusionPass::recordGtao(VkCommandBuffer cmd, const Inputs& in,
                                      const ImageRef& noisy) const {
    VkDescriptorBufferInfo cameraInfo{in.camera->handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorImageInfo depth{pointSampler_.handle(), in.depth.view(),
                                VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorImageInfo normal{pointSampler_.handle(), in.normalRoughMetal.view(),
                                 VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorImageInfo output{VK_NULL_HANDLE, noisy.view(), VK_IMAGE_LAYOUT_GENERAL};
    const VkWriteDescriptorSet writes[] = {
        uniformBufferWrite(CAMERA_BINDING, &cameraInfo),
        sampledImageWrite(AO_BINDING_DEPTH, &depth),
        sampledImageWrite(AO_BINDING_NORMAL, &normal),
        storageImageWrite(AO_BINDING_OUTPUT, &output),
    };
    const Push push{in.settings.radius, in.settings.slices, in.settings.steps, 0.0f};
    gtao_.bind(cmd);
    gtao_.pushDescriptors(cmd, writes);
    gtao_.pushConstants(cmd, &push, sizeof(push));
    vkCmdDispatch(cmd, groups(noisy.desc().width), groups(noisy.desc().height), 1);
}

void AmbientOcclusionPass::recordDenoise(VkCommandBuffer cmd, const Inputs& in,
                                         const ImageRef& noisy, const ImageRef& filtered) const {
    VkDescriptorBufferInfo cameraInfo{in.camera->handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorImageInfo depth{pointSampler_.handle(), in.depth.view(),
                                VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorImageInfo normal{pointSampler_.handle(), in.normalRoughMetal.view(),
                                 VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorImageInfo input{pointSampler_.handle(), noisy.view(),
                                VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorImageInfo output{VK_NULL_HANDLE, filtered.view(), VK_IMAGE_LAYOUT_GENERAL};
    const VkWriteDescriptorSet writes[] = {
        uniformBufferWrite(CAMERA_BINDING, &cameraInfo),
        sampledImageWrite(AO_BINDING_DEPTH, &depth),
        sampledImageWrite(AO_BINDING_NORMAL, &normal),
        sampledImageWrite(AO_BINDING_INPUT, &input),
        storageImageWrite(AO_BINDING_SECOND_OUTPUT, &output),
    };
    denoise_.bind(cmd);
    denoise_.pushDescriptors(cmd, writes);
    vkCmdDispatch(cmd, groups(filtered.desc().width), groups(filtered.desc().height), 1);
}

void AmbientOcclusionPass::recordReference(VkCommandBuffer cmd, const Inputs& in,
                                           const ImageRef& occlusion,
                                           const ImageRef& specular) const {
    VkDescriptorBufferInfo cameraInfo{in.camera->handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorImageInfo depth{pointSampler_.handle(), in.depth.view(),
                                VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorImageInfo normal{pointSampler_.handle(), in.normalRoughMetal.view(),
                                 VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorImageInfo output{VK_NULL_HANDLE, occlusion.view(), VK_IMAGE_LAYOUT_GENERAL};
    VkDescriptorImageInfo second{VK_NULL_HANDLE, specular.view(), VK_IMAGE_LAYOUT_GENERAL};
    const VkWriteDescriptorSet writes[] = {
        uniformBufferWrite(CAMERA_BINDING, &cameraInfo),
        sampledImageWrite(AO_BINDING_DEPTH, &depth),
        sampledImageWrite(AO_BINDING_NORMAL, &normal),
        storageImageWrite(AO_BINDING_OUTPUT, &output),
        storageImageWrite(AO_BINDING_SECOND_OUTPUT, &second),
    };
    const Push push{in.settings.radius, in.settings.referenceRays, in.settings.referenceSteps,
                    in.settings.referenceThickness};
    reference_.bind(cmd);
    reference_.pushDescriptors(cmd, writes);
    reference_.pushConstants(cmd, &push, sizeof(push));
    vkCmdDispatch(cmd, groups(occlusion.desc().width), groups(occlusion.desc().height), 1);
}

}  // namespace candela::render
