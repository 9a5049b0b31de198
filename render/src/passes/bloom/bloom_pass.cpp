#include "passes/bloom/bloom_pass.h"

#include <algorithm>

#include "candela/render/gpu_image.h"
#include "shaders/bloom_composite.comp.spv.h"
#include "shaders/bloom_downsample.comp.spv.h"

namespace candela::render {

namespace {

struct CompositePush {
    float strength;
    uint32_t levelCount;
};

}  // namespace

BloomPass::BloomPass(GpuContext& context) : linear_(context, SamplerDesc{}) {
    const DescriptorBinding down[] = {
        {BLOOM_DOWNSAMPLE_BINDING_SOURCE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
         VK_SHADER_STAGE_COMPUTE_BIT},
        {BLOOM_DOWNSAMPLE_BINDING_TARGET, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
         VK_SHADER_STAGE_COMPUTE_BIT},
    };
    downsample_ = Pipeline::compute(context, bloom_downsample_comp_spv, down, 0);
    std::vector<DescriptorBinding> composite = {{BLOOM_COMPOSITE_BINDING_HDR,
                                                 VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
                                                 VK_SHADER_STAGE_COMPUTE_BIT}};
    for (uint32_t i = 0; i < BLOOM_MAX_LEVELS; ++i) {
        composite.push_back({BLOOM_COMPOSITE_BINDING_FIRST_LEVEL + i,
                             VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                             VK_SHADER_STAGE_COMPUTE_BIT});
    }
    composite_ =
        Pipeline::compute(context, bloom_composite_comp_spv, composite, sizeof(CompositePush));
}

uint32_t BloomPass::levelCount(uint32_t width, uint32_t height) {
    uint32_t levels = 0;
    uint32_t smaller = std::min(width, height);
    while (levels < BLOOM_MAX_LEVELS && (smaller >> (levels + 1)) >= 4)
        ++levels;
    return std::max(levels, 1u);
}

ImageDesc BloomPass::levelDesc(uint32_t level, uint32_t width, uint32_t height) {
    return {VK_FORMAT_R32G32B32A32_SFLOAT,
            std::max(width >> (level + 1), 1u),
            std::max(height >> (level + 1), 1u),
            1,
            false,
            VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT};
}

void BloomPass::recordDownsample(VkCommandBuffer cmd, const ImageRef& source,
                                 const ImageRef& target) const {
    VkDescriptorImageInfo sourceInfo{VK_NULL_HANDLE, source.view(), VK_IMAGE_LAYOUT_GENERAL};
    VkDescriptorImageInfo targetInfo{VK_NULL_HANDLE, target.view(), VK_IMAGE_LAYOUT_GENERAL};
    const VkWriteDescriptorSet writes[] = {
        storageImageWrite(BLOOM_DOWNSAMPLE_BINDING_SOURCE, &sourceInfo),
        storageImageWrite(BLOOM_DOWNSAMPLE_BINDING_TARGET, &targetInfo)};
    downsample_.bind(cmd);
    downsample_.pushDescriptors(cmd, writes);
    vkCmdDispatch(cmd, (target.desc().width + 7) / 8, (target.desc().height + 7) / 8, 1);
}

void BloomPass::recordComposite(VkCommandBuffer cmd, const ImageRef& hdr,
                                const std::array<ImageRef, BLOOM_MAX_LEVELS>& levels,
                                uint32_t levelCount, float strength) const {
    VkDescriptorImageInfo hdrInfo{VK_NULL_HANDLE, hdr.view(), VK_IMAGE_LAYOUT_GENERAL};
    std::array<VkDescriptorImageInfo, BLOOM_MAX_LEVELS> levelInfo{};
    std::vector<VkWriteDescriptorSet> writes = {
        storageImageWrite(BLOOM_COMPOSITE_BINDING_HDR, &hdrInfo)};
    for (uint32_t i = 0; i < BLOOM_MAX_LEVELS; ++i) {
        // Unused slots repeat the last level: every binding must hold a valid image.
        const ImageRef& level = levels[std::min(i, levelCount - 1)];
        levelInfo[i] = {linear_.handle(), level.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
        writes.push_back(sampledImageWrite(BLOOM_COMPOSITE_BINDING_FIRST_LEVEL + i, &levelInfo[i]));
    }
    CompositePush push{strength, levelCount};
    composite_.bind(cmd);
    composite_.pushDescriptors(cmd, writes);
    composite_.pushConstants(cmd, &push, sizeof(push));
    vkCmdDispatch(cmd, (hdr.desc().width + 7) / 8, (hdr.desc().height + 7) / 8, 1);
}

}  // namespace candela::render
