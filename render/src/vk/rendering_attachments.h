#pragma once
// Dynamic rendering's attachments and the rendering over them (the whole target, one layer):
// a pass states what each attachment holds when rendering begins (load), what stays (store)
// and its clear value; the structures' other fields are the same everywhere.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>

namespace candela::render {

inline VkRenderingAttachmentInfo renderingAttachment(VkImageView view, VkImageLayout layout,
                                                     VkAttachmentLoadOp load,
                                                     VkAttachmentStoreOp store,
                                                     VkClearValue clear = {}) {
    VkRenderingAttachmentInfo info{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    info.imageView = view;
    info.imageLayout = layout;
    info.loadOp = load;
    info.storeOp = store;
    info.clearValue = clear;
    return info;
}

// The clear value of a reverse-Z depth target: 0 is infinitely far (nothing in the way).
inline VkClearValue reverseDepthClear() {
    VkClearValue clear{};
    clear.depthStencil = {0.0f, 0};
    return clear;
}

// `colors` and `depth` must outlive the returned structure, which points at them.
inline VkRenderingInfo renderingInfo(uint32_t width, uint32_t height,
                                     std::span<const VkRenderingAttachmentInfo> colors,
                                     const VkRenderingAttachmentInfo* depth = nullptr) {
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, {width, height}};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = uint32_t(colors.size());
    rendering.pColorAttachments = colors.empty() ? nullptr : colors.data();
    rendering.pDepthAttachment = depth;
    return rendering;
}

}  // namespace candela::render
