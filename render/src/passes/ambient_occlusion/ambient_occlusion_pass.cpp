#include "passes/ambient_occlusion/ambient_occlusion_pass.h"

#include <cmath>

#include "candela/render/gpu_context.h"
#include "candela/render/gpu_image.h"
#include "passes/ambient_occlusion/ambient_occlusion_bindings.h"
#include "shaders/ao_denoise.comp.spv.h"
#include "shaders/ao_reference.comp.spv.h"
#include "shaders/ao_temporal.comp.spv.h"
#include "shaders/gtao.comp.spv.h"

namespace candela::render {

namespace {

// The push block of all three shaders.
struct Push {
    float radius;
    uint32_t slices;  // GTAO: slices; reference: rays
    uint32_t steps;
    float thickness;
    glm::vec2 frameRotation;  // gtao.comp only
    uint32_t specularSlice;   // gtao.comp only
};

struct TemporalPush {
    uint32_t historyValid;
    uint32_t maxFrames;
};

constexpr VkShaderStageFlags kCompute = VK_SHADER_STAGE_COMPUTE_BIT;

uint32_t groups(uint32_t pixels) {
    return (pixels + 7) / 8;
}

// GTAO and the reference read depth and normals and write the occlusion and the specular
// lobe's visibility through the same bindings; only the pipeline and the push differ.
void recordOcclusion(VkCommandBuffer cmd, const Pipeline& pipeline, VkSampler pointSampler,
                     const AmbientOcclusionPass::Inputs& in, const Push& push,
                     const ImageRef& occlusion, const ImageRef& specular) {
    VkDescriptorBufferInfo cameraInfo{in.camera->handle(), 0, VK_WHOLE_SIZE};
    VkDescriptorImageInfo depth{pointSampler, in.depth.view(),
                                VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorImageInfo normal{pointSampler, in.normalRoughMetal.view(),
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
    pipeline.bind(cmd);
    pipeline.pushDescriptors(cmd, writes);
    pipeline.pushConstants(cmd, &push, sizeof(push));
    vkCmdDispatch(cmd, groups(occlusion.desc().width), groups(occlusion.desc().height), 1);
}

}  // namespace

AmbientOcclusionPass::AmbientOcclusionPass(GpuContext& context)
    : pointSampler_(context, SamplerDesc{VK_FILTER_NEAREST}) {
    const DescriptorBinding gtao[] = {
        {CAMERA_BINDING, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kCompute},
        {AO_BINDING_DEPTH, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
        {AO_BINDING_NORMAL, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
        {AO_BINDING_OUTPUT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kCompute},
        {AO_BINDING_SECOND_OUTPUT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kCompute},
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
    const DescriptorBinding temporal[] = {
        {CAMERA_BINDING, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kCompute},
        {AO_BINDING_DEPTH, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
        {AO_BINDING_NORMAL, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
        {AO_BINDING_INPUT, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
        {AO_BINDING_MOTION, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
        {AO_BINDING_HISTORY, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, kCompute},
        {AO_BINDING_SECOND_OUTPUT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kCompute},
        {AO_BINDING_HISTORY_OUTPUT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kCompute},
    };
    temporal_ = Pipeline::compute(context, ao_temporal_comp_spv, temporal, sizeof(TemporalPush));
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

ImageDesc AmbientOcclusionPass::historyDesc(uint32_t width, uint32_t height) {
    // Transfer destination: cleared by an upload when made.
    return {
        VK_FORMAT_R32G32B32A32_UINT,
        width,
        height,
        1,
        false,
        VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT};
}

glm::vec2 AmbientOcclusionPass::frameRotation(uint32_t frame) {
    // Roberts' R2 sequence: consecutive frames fill the (rotation, offset) square evenly.
    constexpr double kA1 = 0.7548776662466927, kA2 = 0.5698402909980532;
    const double n = double(frame % 4096u);
    return {float(n * kA1 - std::floor(n * kA1)), float(n * kA2 - std::floor(n * kA2))};
}

void AmbientOcclusionPass::recordGtao(VkCommandBuffer cmd, const Inputs& in, const ImageRef& noisy,
                                      const ImageRef& specular) const {
    const uint32_t specularSlice = in.settings.specular == AoSpecular::HorizonSlice ? 1u : 0u;
    const Push push{in.settings.radius, in.settings.slices, in.settings.steps, 0.0f,
                    in.frameRotation,   specularSlice};
    recordOcclusion(cmd, gtao_, pointSampler_.handle(), in, push, noisy, specular);
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

void AmbientOcclusionPass::recordTemporal(VkCommandBuffer cmd, const Inputs& in,
                                          const TemporalInputs& temporal,
                                          const ImageRef& accumulated,
                                          const ImageRef& historyOut) const {
    VkDescriptorBufferInfo cameraInfo{in.camera->handle(), 0, VK_WHOLE_SIZE};
    auto sampled = [this](const ImageRef& image) {
        return VkDescriptorImageInfo{pointSampler_.handle(), image.view(),
                                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    };
    const VkDescriptorImageInfo depth = sampled(in.depth);
    const VkDescriptorImageInfo normal = sampled(in.normalRoughMetal);
    const VkDescriptorImageInfo current = sampled(temporal.current);
    const VkDescriptorImageInfo motion = sampled(temporal.motion);
    const VkDescriptorImageInfo history = sampled(temporal.history);
    VkDescriptorImageInfo output{VK_NULL_HANDLE, accumulated.view(), VK_IMAGE_LAYOUT_GENERAL};
    VkDescriptorImageInfo written{VK_NULL_HANDLE, historyOut.view(), VK_IMAGE_LAYOUT_GENERAL};
    const VkWriteDescriptorSet writes[] = {
        uniformBufferWrite(CAMERA_BINDING, &cameraInfo),
        sampledImageWrite(AO_BINDING_DEPTH, &depth),
        sampledImageWrite(AO_BINDING_NORMAL, &normal),
        sampledImageWrite(AO_BINDING_INPUT, &current),
        sampledImageWrite(AO_BINDING_MOTION, &motion),
        sampledImageWrite(AO_BINDING_HISTORY, &history),
        storageImageWrite(AO_BINDING_SECOND_OUTPUT, &output),
        storageImageWrite(AO_BINDING_HISTORY_OUTPUT, &written),
    };
    const TemporalPush push{temporal.historyValid ? 1u : 0u, temporal.maxFrames};
    temporal_.bind(cmd);
    temporal_.pushDescriptors(cmd, writes);
    temporal_.pushConstants(cmd, &push, sizeof(push));
    vkCmdDispatch(cmd, groups(accumulated.desc().width), groups(accumulated.desc().height), 1);
}

void AmbientOcclusionPass::recordReference(VkCommandBuffer cmd, const Inputs& in,
                                           const ImageRef& occlusion,
                                           const ImageRef& specular) const {
    const Push push{in.settings.radius,
                    in.settings.referenceRays,
                    in.settings.referenceSteps,
                    in.settings.referenceThickness,
                    glm::vec2(0.0f),
                    0u};
    recordOcclusion(cmd, reference_, pointSampler_.handle(), in, push, occlusion, specular);
}

}  // namespace candela::render
