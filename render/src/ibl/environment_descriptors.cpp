#include "ibl/environment_descriptors.h"

#include "candela/render/environment.h"
#include "candela/render/gpu_context.h"
#include "ibl/environment_brdf_lut.h"
#include "vk/sampler.h"

namespace candela::render {

namespace {
constexpr VkImageLayout kRead = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
}

EnvironmentPlaceholders::EnvironmentPlaceholders(GpuContext& context)
    : cube_(context, {VK_FORMAT_R16G16B16A16_SFLOAT, 1, 1, 1, true,
                      VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT}),
      lut_(context, {VK_FORMAT_R16G16B16A16_UNORM, 1, 1, 1, false,
                     VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT}),
      buffer_(context, 9 * 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryLocation::Device),
      sampler_(std::make_unique<Sampler>(context, SamplerDesc{})) {
    context.submitAndWait([&](VkCommandBuffer cmd) {
        // Cleared to zero, not left undefined: a variant that binds them may still read them.
        const VkClearColorValue zero{};
        for (const GpuImage* image : {&cube_, &lut_}) {
            transitionImage(cmd, *image, VK_IMAGE_LAYOUT_UNDEFINED,
                            VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_NONE, 0,
                            VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
            const VkImageSubresourceRange all{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, image->layers()};
            vkCmdClearColorImage(cmd, image->handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &zero,
                                 1, &all);
            transitionImage(
                cmd, *image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, kRead,
                VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                VK_ACCESS_2_SHADER_READ_BIT);
        }
    });
}

EnvironmentPlaceholders::~EnvironmentPlaceholders() = default;

EnvironmentDescriptors EnvironmentPlaceholders::describe(const Environment* environment,
                                                         const EnvironmentBrdfLut* lut,
                                                         const GpuBuffer* samplingTable) const {
    EnvironmentDescriptors d;
    d.environment = {sampler_->handle(), cube_.view(), kRead};
    d.prefiltered = d.environment;
    d.brdfLut = {sampler_->handle(), lut_.view(), kRead};
    d.irradianceSh = {buffer_.handle(), 0, VK_WHOLE_SIZE};
    d.samplingTable = d.irradianceSh;
    if (lut) d.brdfLut = {lut->sampler(), lut->image().view(), kRead};
    if (environment && lut) {
        d.environment = {environment->sampler(), environment->cube().view(), kRead};
        d.prefiltered = {environment->sampler(), environment->prefiltered().view(), kRead};
        d.irradianceSh = {environment->irradianceSh().handle(), 0, VK_WHOLE_SIZE};
        d.prefilteredMipCount = float(environment->prefiltered().desc().mipLevels);
    }
    if (samplingTable) d.samplingTable = {samplingTable->handle(), 0, VK_WHOLE_SIZE};
    return d;
}

}  // namespace candela::render
