#include "ibl/environment_filter.h"

#include <algorithm>

#include "candela/render/gpu_buffer.h"
#include "candela/render/gpu_context.h"
#include "candela/render/gpu_image.h"
#include "ibl/environment_precompute.h"
#include "ibl/ibl_bindings.h"
#include "shaders/cube_downsample.comp.spv.h"
#include "shaders/irradiance_sh.comp.spv.h"
#include "shaders/prefilter_ggx.comp.spv.h"
#include "vk/memory_barrier.h"

namespace candela::render {

namespace {

constexpr uint32_t kShFaceSize = 32;

const DescriptorBinding kSampleAndWrite[] = {
    {IBL_BINDING_SOURCE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_COMPUTE_BIT},
    {IBL_BINDING_DESTINATION, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_SHADER_STAGE_COMPUTE_BIT},
};
const DescriptorBinding kSampleAndBuffer[] = {
    {IBL_BINDING_SOURCE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_COMPUTE_BIT},
    {IBL_BINDING_DESTINATION, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
};

uint32_t groups(uint32_t size) {
    return (size + 7) / 8;
}

void dispatchFaces(VkCommandBuffer cmd, const Pipeline& pipeline, VkSampler sampler,
                   VkImageView input, VkImageView output, const void* push, uint32_t pushBytes,
                   uint32_t faceSize) {
    VkDescriptorImageInfo in{sampler, input, VK_IMAGE_LAYOUT_GENERAL};
    VkDescriptorImageInfo out{VK_NULL_HANDLE, output, VK_IMAGE_LAYOUT_GENERAL};
    VkWriteDescriptorSet writes[] = {sampledImageWrite(IBL_BINDING_SOURCE, &in),
                                     storageImageWrite(IBL_BINDING_DESTINATION, &out)};
    pipeline.bind(cmd);
    pipeline.pushDescriptors(cmd, writes);
    pipeline.pushConstants(cmd, push, pushBytes);
    vkCmdDispatch(cmd, groups(faceSize), groups(faceSize), 6);
}

}  // namespace

EnvironmentViews::EnvironmentViews(GpuContext& context, const GpuImage& cube,
                                   const GpuImage& prefiltered) {
    for (uint32_t mip = 0; mip < cube.desc().mipLevels; ++mip) {
        cubeWrite.emplace_back(context, cube, VK_IMAGE_VIEW_TYPE_2D_ARRAY, mip, 1);
        cubeRead.emplace_back(context, cube, VK_IMAGE_VIEW_TYPE_CUBE, mip, 1);
    }
    for (uint32_t mip = 0; mip < prefiltered.desc().mipLevels; ++mip)
        prefilteredWrite.emplace_back(context, prefiltered, VK_IMAGE_VIEW_TYPE_2D_ARRAY, mip, 1);
}

void environmentWriteBarrier(VkCommandBuffer cmd, const GpuImage& image) {
    // Whole-image: the next dispatch samples what this one wrote (GENERAL stays GENERAL).
    transitionImage(cmd, image, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_GENERAL,
                    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                    VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
}

EnvironmentFilter::EnvironmentFilter(GpuContext& context)
    : linear_(context, {VK_FILTER_LINEAR, false}), trilinear_(context, {VK_FILTER_LINEAR, true}) {
    downsample_ = Pipeline::compute(context, cube_downsample_comp_spv, kSampleAndWrite, 4);
    prefilter_ = Pipeline::compute(context, prefilter_ggx_comp_spv, kSampleAndWrite, 20);
    projectSh_ = Pipeline::compute(context, irradiance_sh_comp_spv, kSampleAndBuffer, 8);
}

void EnvironmentFilter::recordMips(VkCommandBuffer cmd, const GpuImage& cube,
                                   const EnvironmentViews& views) const {
    const uint32_t cubeFace = cube.desc().width;
    for (uint32_t mip = 1; mip < cube.desc().mipLevels; ++mip) {
        environmentWriteBarrier(cmd, cube);
        uint32_t face = std::max(cubeFace >> mip, 1u);
        dispatchFaces(cmd, downsample_, linear_.handle(), views.cubeRead[mip - 1].handle(),
                      views.cubeWrite[mip].handle(), &face, sizeof(face), face);
    }
    environmentWriteBarrier(cmd, cube);
}

void EnvironmentFilter::recordPrefilter(VkCommandBuffer cmd, const GpuImage& cube,
                                        const GpuImage& prefiltered,
                                        const EnvironmentViews& views) const {
    const uint32_t levels = prefiltered.desc().mipLevels;
    for (uint32_t mip = 0; mip < levels; ++mip) {
        struct {
            uint32_t faceSize;
            uint32_t sampleCount;
            float roughness;
            float environmentFaceSize;
            float environmentMipCount;
        } push{std::max(prefiltered.desc().width >> mip, 1u), kPrefilterSampleCount,
               levels > 1 ? float(mip) / float(levels - 1) : 1.0f, float(cube.desc().width),
               float(cube.desc().mipLevels)};
        dispatchFaces(cmd, prefilter_, trilinear_.handle(), cube.view(),
                      views.prefilteredWrite[mip].handle(), &push, sizeof(push), push.faceSize);
    }
}

void EnvironmentFilter::recordIrradiance(VkCommandBuffer cmd, const GpuImage& cube,
                                         const GpuBuffer& irradianceSh) const {
    const uint32_t cubeFace = cube.desc().width;
    uint32_t shMip = 0;
    while ((cubeFace >> shMip) > kShFaceSize && shMip + 1 < cube.desc().mipLevels)
        ++shMip;
    struct {
        uint32_t faceSize;
        float lod;
    } shPush{std::max(cubeFace >> shMip, 1u), float(shMip)};
    VkDescriptorImageInfo in{trilinear_.handle(), cube.view(), VK_IMAGE_LAYOUT_GENERAL};
    VkDescriptorBufferInfo out{irradianceSh.handle(), 0, VK_WHOLE_SIZE};
    VkWriteDescriptorSet writes[] = {sampledImageWrite(IBL_BINDING_SOURCE, &in),
                                     storageBufferWrite(IBL_BINDING_DESTINATION, &out)};
    projectSh_.bind(cmd);
    projectSh_.pushDescriptors(cmd, writes);
    projectSh_.pushConstants(cmd, &shPush, sizeof(shPush));
    vkCmdDispatch(cmd, 1, 1, 1);
}

void EnvironmentFilter::finish(VkCommandBuffer cmd, const GpuImage& cube,
                               const GpuImage& prefiltered) {
    for (const GpuImage* image : {&cube, &prefiltered}) {
        transitionImage(
            cmd, *image, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
            VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
            VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT);
    }
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT);
}

}  // namespace candela::render
