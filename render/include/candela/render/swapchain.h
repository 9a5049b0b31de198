#pragma once
// Presentation to a window surface: acquire, blit the tonemapped frame, present.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

namespace candela::render {

class GpuContext;
class GpuImage;

class Swapchain {
public:
    Swapchain(GpuContext& context, VkSurfaceKHR surface, uint32_t width, uint32_t height);
    ~Swapchain();
    Swapchain(const Swapchain&) = delete;
    Swapchain& operator=(const Swapchain&) = delete;

    // Rebuilds for a new window size (after VK_ERROR_OUT_OF_DATE_KHR or a resize event).
    void recreate(uint32_t width, uint32_t height);
    VkExtent2D extent() const { return extent_; }

    // False when the swapchain is out of date and must be recreated.
    bool acquire(VkSemaphore imageAvailable, uint32_t& imageIndex);
    // Records a scaled blit of `source` (TRANSFER_SRC_OPTIMAL) into the image, leaving it
    // ready to present.
    void recordBlit(VkCommandBuffer cmd, const GpuImage& source, uint32_t imageIndex) const;
    // Signalled by the frame's submission, waited on by present; one per image.
    VkSemaphore renderFinished(uint32_t imageIndex) const { return renderFinished_[imageIndex]; }
    bool present(uint32_t imageIndex);

private:
    void create(uint32_t width, uint32_t height);
    void destroy();

    GpuContext& context_;
    VkSurfaceKHR surface_;
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    VkExtent2D extent_{};
    std::vector<VkImage> images_;
    std::vector<VkSemaphore> renderFinished_;
};

}  // namespace candela::render
