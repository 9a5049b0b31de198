#include "overlay_pass_support.h"

#include <cstring>
#include <stdexcept>

#include "candela/render/gpu_context.h"

namespace candela::ui {

VkSampler makeClampedLinearSampler(render::GpuContext& context) {
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = VK_FILTER_LINEAR;
    info.minFilter = VK_FILTER_LINEAR;
    info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    info.addressModeU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    info.addressModeV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    info.maxLod = 0.0f;
    VkSampler sampler = VK_NULL_HANDLE;
    if (vkCreateSampler(context.device(), &info, nullptr, &sampler) != VK_SUCCESS)
        throw std::runtime_error("UI pass: vkCreateSampler failed");
    return sampler;
}

void uploadTexture(render::GpuContext& context, render::GpuImage& image, const void* pixels,
                   VkDeviceSize bytes, bool fresh) {
    render::GpuBuffer staging(context, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                              render::MemoryLocation::HostVisible);
    std::memcpy(staging.mapped(), pixels, bytes);
    context.submitAndWait([&](VkCommandBuffer cmd) {
        render::transitionImage(
            cmd, image,
            fresh ? VK_IMAGE_LAYOUT_UNDEFINED : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
            VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
            fresh ? VK_PIPELINE_STAGE_2_NONE : VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, 0,
            VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {image.desc().width, image.desc().height, 1};
        vkCmdCopyBufferToImage(cmd, staging.handle(), image.handle(),
                               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        render::transitionImage(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                                VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                                VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    });
}

void growHostBuffer(render::GpuContext& context, render::GpuBuffer& buffer, VkDeviceSize bytes,
                    VkBufferUsageFlags usage, VkDeviceSize minimum) {
    if (buffer.handle() != VK_NULL_HANDLE && buffer.size() >= bytes) return;
    VkDeviceSize size = minimum;
    while (size < bytes)
        size *= 2;
    buffer = render::GpuBuffer(context, size, usage, render::MemoryLocation::HostVisible);
}

void beginOverlayRendering(VkCommandBuffer cmd, const render::GpuImage& target) {
    const std::uint32_t width = target.desc().width, height = target.desc().height;
    VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    color.imageView = target.view();
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, {width, height}};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachments = &color;
    vkCmdBeginRendering(cmd, &rendering);
    VkViewport viewport{0.0f, 0.0f, float(width), float(height), 0.0f, 1.0f};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
}

}  // namespace candela::ui
