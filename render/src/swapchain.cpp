#include "candela/render/swapchain.h"

#include <algorithm>
#include <stdexcept>

#include "candela/render/gpu_context.h"
#include "candela/render/gpu_image.h"
#include "vk/vk_check.h"

namespace candela::render {

namespace {

// A UNORM format: the frame is already sRGB-encoded by the tonemapper, so an _SRGB
// swapchain would encode it twice.
VkSurfaceFormatKHR chooseFormat(VkPhysicalDevice device, VkSurfaceKHR surface) {
    uint32_t count = 0;
    vkGetPhysicalDeviceSurfaceFormatsKHR(device, surface, &count, nullptr);
    std::vector<VkSurfaceFormatKHR> formats(count);
    vkGetPhysicalDeviceSurfaceFormatsKHR(device, surface, &count, formats.data());
    for (const VkSurfaceFormatKHR& f : formats) {
        if (f.format == VK_FORMAT_B8G8R8A8_UNORM || f.format == VK_FORMAT_R8G8B8A8_UNORM) return f;
    }
    if (formats.empty()) throw std::runtime_error("window surface reports no formats");
    return formats.front();
}

}  // namespace

Swapchain::Swapchain(GpuContext& context, VkSurfaceKHR surface, uint32_t width, uint32_t height)
    : context_(context), surface_(surface) {
    create(width, height);
}

Swapchain::~Swapchain() {
    // The last present still waits on its render-finished semaphore: no fence covers a present,
    // so only an idle device makes the semaphores free to destroy (a window closed right after
    // a present failed validation's VUID-vkDestroySemaphore-semaphore-01137 now and then).
    vkDeviceWaitIdle(context_.device());
    destroy();
}

void Swapchain::recreate(uint32_t width, uint32_t height) {
    vkDeviceWaitIdle(context_.device());
    destroy();
    create(width, height);
}

void Swapchain::create(uint32_t width, uint32_t height) {
    VkPhysicalDevice physical = context_.physicalDevice();
    VkBool32 supported = VK_FALSE;
    vkGetPhysicalDeviceSurfaceSupportKHR(physical, context_.queueFamily(), surface_, &supported);
    if (!supported) throw std::runtime_error("the render queue cannot present to this window");

    VkSurfaceCapabilitiesKHR caps;
    CANDELA_VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(physical, surface_, &caps));
    if (caps.currentExtent.width != UINT32_MAX) {
        extent_ = caps.currentExtent;
    } else {
        extent_.width = std::clamp(width, caps.minImageExtent.width, caps.maxImageExtent.width);
        extent_.height = std::clamp(height, caps.minImageExtent.height, caps.maxImageExtent.height);
    }
    uint32_t imageCount = caps.minImageCount + 1;
    if (caps.maxImageCount > 0) imageCount = std::min(imageCount, caps.maxImageCount);

    VkSurfaceFormatKHR format = chooseFormat(physical, surface_);
    VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    info.surface = surface_;
    info.minImageCount = imageCount;
    info.imageFormat = format.format;
    info.imageColorSpace = format.colorSpace;
    info.imageExtent = extent_;
    info.imageArrayLayers = 1;
    info.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    info.presentMode = VK_PRESENT_MODE_FIFO_KHR;  // always available
    info.clipped = VK_TRUE;
    CANDELA_VK_CHECK(vkCreateSwapchainKHR(context_.device(), &info, nullptr, &swapchain_));

    uint32_t count = 0;
    vkGetSwapchainImagesKHR(context_.device(), swapchain_, &count, nullptr);
    images_.resize(count);
    vkGetSwapchainImagesKHR(context_.device(), swapchain_, &count, images_.data());
    renderFinished_.resize(count);
    VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    for (VkSemaphore& s : renderFinished_) {
        CANDELA_VK_CHECK(vkCreateSemaphore(context_.device(), &semaphoreInfo, nullptr, &s));
    }
}

void Swapchain::destroy() {
    for (VkSemaphore s : renderFinished_)
        vkDestroySemaphore(context_.device(), s, nullptr);
    renderFinished_.clear();
    images_.clear();
    if (swapchain_) vkDestroySwapchainKHR(context_.device(), swapchain_, nullptr);
    swapchain_ = VK_NULL_HANDLE;
}

bool Swapchain::acquire(VkSemaphore imageAvailable, uint32_t& imageIndex) {
    VkResult result = vkAcquireNextImageKHR(context_.device(), swapchain_, UINT64_MAX,
                                            imageAvailable, VK_NULL_HANDLE, &imageIndex);
    if (result == VK_ERROR_OUT_OF_DATE_KHR) return false;
    if (result != VK_SUCCESS && result != VK_SUBOPTIMAL_KHR) {
        throwVkError("vkAcquireNextImageKHR", result);
    }
    return true;
}

void Swapchain::recordBlit(VkCommandBuffer cmd, const GpuImage& source, uint32_t imageIndex) const {
    VkImage target = images_[imageIndex];
    auto barrier = [&](VkImageLayout from, VkImageLayout to, VkPipelineStageFlags2 srcStage,
                       VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStage,
                       VkAccessFlags2 dstAccess) {
        VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
        b.srcStageMask = srcStage;
        b.srcAccessMask = srcAccess;
        b.dstStageMask = dstStage;
        b.dstAccessMask = dstAccess;
        b.oldLayout = from;
        b.newLayout = to;
        b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        b.image = target;
        b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
        dependency.imageMemoryBarrierCount = 1;
        dependency.pImageMemoryBarriers = &b;
        vkCmdPipelineBarrier2(cmd, &dependency);
    };
    // The acquire semaphore is waited at the transfer stage, so the layout change chains to it.
    barrier(VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
            VK_PIPELINE_STAGE_2_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
            VK_ACCESS_2_TRANSFER_WRITE_BIT);
    VkImageBlit region{};
    region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.srcOffsets[1] = {int32_t(source.desc().width), int32_t(source.desc().height), 1};
    region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.dstOffsets[1] = {int32_t(extent_.width), int32_t(extent_.height), 1};
    vkCmdBlitImage(cmd, source.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target,
                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region, VK_FILTER_LINEAR);
    barrier(VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
            VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
            VK_PIPELINE_STAGE_2_NONE, 0);
}

bool Swapchain::present(uint32_t imageIndex) {
    VkPresentInfoKHR info{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    info.waitSemaphoreCount = 1;
    info.pWaitSemaphores = &renderFinished_[imageIndex];
    info.swapchainCount = 1;
    info.pSwapchains = &swapchain_;
    info.pImageIndices = &imageIndex;
    VkResult result = vkQueuePresentKHR(context_.queue(), &info);
    if (result == VK_ERROR_OUT_OF_DATE_KHR || result == VK_SUBOPTIMAL_KHR) return false;
    if (result != VK_SUCCESS) throwVkError("vkQueuePresentKHR", result);
    return true;
}

}  // namespace candela::render
