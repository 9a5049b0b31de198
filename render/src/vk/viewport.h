#pragma once
// The viewport and scissor of a raster pass: both cover the same rectangle (the whole target,
// or a tile of an atlas), depth 0 to 1.
#include <vulkan/vulkan.h>

#include <cstdint>

namespace candela::render {

inline void setViewportAndScissor(VkCommandBuffer cmd, const VkRect2D& rect) {
    const VkViewport viewport{float(rect.offset.x),
                              float(rect.offset.y),
                              float(rect.extent.width),
                              float(rect.extent.height),
                              0.0f,
                              1.0f};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &rect);
}

inline void setViewportAndScissor(VkCommandBuffer cmd, uint32_t width, uint32_t height) {
    setViewportAndScissor(cmd, VkRect2D{{0, 0}, {width, height}});
}

}  // namespace candela::render
