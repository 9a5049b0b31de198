#include "passes/forward_transparent/msaa_samples.h"

#include <stdexcept>
#include <string>

#include "candela/render/gpu_context.h"
#include "gbuffer_targets.h"

namespace candela::render {

namespace {

// Sample counts the device renders for `format` as an attachment with `usage`.
VkSampleCountFlags formatSampleCounts(const GpuContext& context, VkFormat format,
                                      VkImageUsageFlags usage) {
    VkImageFormatProperties properties{};
    if (vkGetPhysicalDeviceImageFormatProperties(context.physicalDevice(), format, VK_IMAGE_TYPE_2D,
                                                 VK_IMAGE_TILING_OPTIMAL, usage, 0,
                                                 &properties) != VK_SUCCESS) {
        return VK_SAMPLE_COUNT_1_BIT;
    }
    return properties.sampleCounts;
}

}  // namespace

VkSampleCountFlagBits forwardMsaaSamples(const GpuContext& context, uint32_t requested) {
    if (requested == 1) return VK_SAMPLE_COUNT_1_BIT;
    const VkPhysicalDeviceLimits& limits = context.properties().limits;
    const VkSampleCountFlags supported =
        limits.framebufferColorSampleCounts & limits.framebufferDepthSampleCounts &
        formatSampleCounts(context, VK_FORMAT_R32G32B32A32_SFLOAT,
                           VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT) &
        formatSampleCounts(context, GBufferTargets::kMotionFormat,
                           VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT) &
        formatSampleCounts(context, GBufferTargets::kDepthFormat,
                           VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT);
    const bool known = requested == 2 || requested == 4 || requested == 8;
    if (known && (supported & requested)) return VkSampleCountFlagBits(requested);
    std::string counts = "1";
    for (uint32_t n : {2u, 4u, 8u}) {
        if (supported & n) counts += ", " + std::to_string(n);
    }
    throw std::invalid_argument("MSAA " + std::to_string(requested) + " samples: the device '" +
                                context.properties().deviceName + "' supports " + counts +
                                " for the forward pass's targets");
}

}  // namespace candela::render
