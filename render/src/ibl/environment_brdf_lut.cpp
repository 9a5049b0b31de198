#include "ibl/environment_brdf_lut.h"

#include "candela/render/gpu_context.h"
#include "candela/render/pipeline.h"
#include "cpu_clock.h"
#include "ibl/ibl_bindings.h"
#include "shaders/environment_brdf_lut.comp.spv.h"
#include "vk/memory_barrier.h"
#include "vk/sampler.h"

namespace candela::render {

EnvironmentBrdfLut::EnvironmentBrdfLut(GpuContext& context)
    : image_(context, {VK_FORMAT_R16G16B16A16_UNORM, kSize, kSize, 1, false,
                       VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT}),
      texels_(context, VkDeviceSize(kSize) * kSize * 8,
              VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
              MemoryLocation::HostVisible),
      sampler_(std::make_unique<Sampler>(context, SamplerDesc{VK_FILTER_LINEAR, false})) {
    const CpuClock::time_point start = CpuClock::now();
    const DescriptorBinding bindings[] = {
        {BRDF_LUT_BINDING_TEXELS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT}};
    Pipeline pipeline = Pipeline::compute(context, environment_brdf_lut_comp_spv, bindings, 8);
    context.submitAndWait([&](VkCommandBuffer cmd) {
        VkDescriptorBufferInfo out{texels_.handle(), 0, VK_WHOLE_SIZE};
        VkWriteDescriptorSet writes[] = {storageBufferWrite(BRDF_LUT_BINDING_TEXELS, &out)};
        struct {
            uint32_t size;
            uint32_t sampleCount;
        } push{kSize, kSampleCount};
        pipeline.bind(cmd);
        pipeline.pushDescriptors(cmd, writes);
        pipeline.pushConstants(cmd, &push, sizeof(push));
        vkCmdDispatch(cmd, kSize / 8, kSize / 8, 1);
        memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                      VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                      VK_PIPELINE_STAGE_2_TRANSFER_BIT | VK_PIPELINE_STAGE_2_HOST_BIT,
                      VK_ACCESS_2_TRANSFER_READ_BIT | VK_ACCESS_2_HOST_READ_BIT);
        transitionImage(cmd, image_, VK_IMAGE_LAYOUT_UNDEFINED,
                        VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_NONE, 0,
                        VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {kSize, kSize, 1};
        vkCmdCopyBufferToImage(cmd, texels_.handle(), image_.handle(),
                               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        transitionImage(cmd, image_, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                        VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                        VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_SHADER_READ_BIT);
    });
    buildMs_ = millisecondsSince(start);
}

EnvironmentBrdfLut::~EnvironmentBrdfLut() = default;

VkSampler EnvironmentBrdfLut::sampler() const {
    return sampler_->handle();
}

}  // namespace candela::render
