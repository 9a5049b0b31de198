#include "passes/nonfinite/nonfinite_pass.h"

#include <cstring>

#include "candela/render/gpu_image.h"
#include "passes/nonfinite/nonfinite_bindings.h"
#include "shaders/nonfinite_count.comp.spv.h"
#include "shaders/nonfinite_radiance.comp.spv.h"

namespace candela::render {

namespace {

struct Push {
    uint32_t channels;
};

}  // namespace

NonFinitePass::NonFinitePass(GpuContext& context)
    : nearest_(context, SamplerDesc{VK_FILTER_NEAREST}),
      counts_(context, kSlots * kSlotBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
              MemoryLocation::HostVisible) {
    const DescriptorBinding sampled[] = {
        {NONFINITE_BINDING_IMAGE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
         VK_SHADER_STAGE_COMPUTE_BIT},
        {NONFINITE_BINDING_COUNTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
    };
    sampled_ = Pipeline::compute(context, nonfinite_count_comp_spv, sampled, sizeof(Push));
    const DescriptorBinding storage[] = {
        {NONFINITE_BINDING_IMAGE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_SHADER_STAGE_COMPUTE_BIT},
        {NONFINITE_BINDING_COUNTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
    };
    radiance_ = Pipeline::compute(context, nonfinite_radiance_comp_spv, storage, sizeof(Push));
}

void NonFinitePass::clear() const {
    std::memset(counts_.mapped(), 0, counts_.size());
}

void NonFinitePass::recordRadianceCount(VkCommandBuffer cmd, const ImageRef& radiance) const {
    VkDescriptorImageInfo info{VK_NULL_HANDLE, radiance.view(), VK_IMAGE_LAYOUT_GENERAL};
    dispatch(cmd, radiance_, storageImageWrite(NONFINITE_BINDING_IMAGE, &info), kRadianceSlot, 3,
             radiance.desc());
}

void NonFinitePass::recordCount(VkCommandBuffer cmd, const ImageRef& image, uint32_t slot,
                                bool storage) const {
    if (storage) {
        VkDescriptorImageInfo info{VK_NULL_HANDLE, image.view(), VK_IMAGE_LAYOUT_GENERAL};
        dispatch(cmd, radiance_, storageImageWrite(NONFINITE_BINDING_IMAGE, &info), slot, 4,
                 image.desc());
        return;
    }
    VkDescriptorImageInfo info{nearest_.handle(), image.view(),
                               VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    dispatch(cmd, sampled_, sampledImageWrite(NONFINITE_BINDING_IMAGE, &info), slot, 4,
             image.desc());
}

void NonFinitePass::dispatch(VkCommandBuffer cmd, const Pipeline& pipeline,
                             const VkWriteDescriptorSet& image, uint32_t slot, uint32_t channels,
                             const ImageDesc& desc) const {
    VkDescriptorBufferInfo countInfo{counts_.handle(), slot * kSlotBytes, sizeof(uint32_t)};
    const VkWriteDescriptorSet writes[] = {
        image, storageBufferWrite(NONFINITE_BINDING_COUNTS, &countInfo)};
    const Push push{channels};
    pipeline.bind(cmd);
    pipeline.pushDescriptors(cmd, writes);
    pipeline.pushConstants(cmd, &push, sizeof(push));
    vkCmdDispatch(cmd, (desc.width + 7) / 8, (desc.height + 7) / 8, 1);
}

uint32_t NonFinitePass::count(uint32_t slot) const {
    uint32_t value;
    std::memcpy(&value, static_cast<const char*>(counts_.mapped()) + slot * kSlotBytes,
                sizeof(value));
    return value;
}

}  // namespace candela::render
