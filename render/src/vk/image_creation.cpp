#include "vk/image_creation.h"

#include "vk/vk_check.h"

namespace candela::render {

VkImageAspectFlags aspectOf(VkFormat format) {
    const bool depth = format == VK_FORMAT_D32_SFLOAT || format == VK_FORMAT_D16_UNORM ||
                       format == VK_FORMAT_D24_UNORM_S8_UINT ||
                       format == VK_FORMAT_D32_SFLOAT_S8_UINT;
    return depth ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
}

VkImage createImage(VkDevice device, const ImageDesc& desc) {
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.flags = desc.cube ? VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT : 0;
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = desc.format;
    info.extent = {desc.width, desc.height, 1};
    info.mipLevels = desc.mipLevels;
    info.arrayLayers = desc.cube ? 6u : 1u;
    info.samples = desc.samples;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = desc.usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkImage image = VK_NULL_HANDLE;
    CANDELA_VK_CHECK(vkCreateImage(device, &info, nullptr, &image));
    return image;
}

VkImageView createWholeView(VkDevice device, VkImage image, const ImageDesc& desc) {
    VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    info.image = image;
    info.viewType = desc.cube ? VK_IMAGE_VIEW_TYPE_CUBE : VK_IMAGE_VIEW_TYPE_2D;
    info.format = desc.format;
    info.subresourceRange = {aspectOf(desc.format), 0, desc.mipLevels, 0, desc.cube ? 6u : 1u};
    VkImageView view = VK_NULL_HANDLE;
    CANDELA_VK_CHECK(vkCreateImageView(device, &info, nullptr, &view));
    return view;
}

}  // namespace candela::render
