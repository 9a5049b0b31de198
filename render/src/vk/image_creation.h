#pragma once
// Whole-image creation shared by GpuImage (which binds memory from the allocator) and the frame
// graph's transients (which bind it from the graph's pool).
#include <vulkan/vulkan.h>

#include "candela/render/gpu_image.h"

namespace candela::render {

// Depth formats are viewed and barriered through the depth aspect, the rest through colour.
VkImageAspectFlags aspectOf(VkFormat format);
// An optimally tiled 2D (or cube) image for `desc`, without memory.
VkImage createImage(VkDevice device, const ImageDesc& desc);
// A view of every mip and layer of `image`.
VkImageView createWholeView(VkDevice device, VkImage image, const ImageDesc& desc);

}  // namespace candela::render
