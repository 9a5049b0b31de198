#include "candela/render/gpu_image.h"

#include <utility>

#include "candela/render/gpu_context.h"
#include "vk/image_creation.h"
#include "vk/memory_allocator.h"
#include "vk/vk_check.h"

namespace candela::render {

GpuImage::GpuImage(GpuContext& context, const ImageDesc& desc)
    : device_(context.device()), allocator_(&context.memoryAllocator()), desc_(desc) {
    image_ = createImage(device_, desc);

    try {
        memory_ = allocator_->allocateFor(image_, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        CANDELA_VK_CHECK(vkBindImageMemory(device_, image_, memory_.memory, memory_.offset));
    } catch (...) {
        release();
        throw;
    }

    try {
        view_ = createWholeView(device_, image_, desc);
    } catch (...) {
        release();
        throw;
    }
}

VkImageAspectFlags GpuImage::aspect() const {
    return aspectOf(desc_.format);
}

GpuImage::~GpuImage() {
    release();
}

GpuImage::GpuImage(GpuImage&& other) noexcept {
    *this = std::move(other);
}

GpuImage& GpuImage::operator=(GpuImage&& other) noexcept {
    if (this != &other) {
        release();
        device_ = std::exchange(other.device_, VK_NULL_HANDLE);
        allocator_ = std::exchange(other.allocator_, nullptr);
        image_ = std::exchange(other.image_, VK_NULL_HANDLE);
        view_ = std::exchange(other.view_, VK_NULL_HANDLE);
        memory_ = std::exchange(other.memory_, MemoryAllocation{});
        desc_ = other.desc_;
    }
    return *this;
}

void GpuImage::release() {
    if (!device_) return;
    if (view_) vkDestroyImageView(device_, view_, nullptr);
    if (image_) vkDestroyImage(device_, image_, nullptr);
    allocator_->free(memory_);
    view_ = VK_NULL_HANDLE;
    image_ = VK_NULL_HANDLE;
    memory_ = {};
}

void transitionImage(VkCommandBuffer cmd, const GpuImage& image, VkImageLayout from,
                     VkImageLayout to, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                     VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess) {
    VkImageMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    barrier.srcStageMask = srcStage;
    barrier.srcAccessMask = srcAccess;
    barrier.dstStageMask = dstStage;
    barrier.dstAccessMask = dstAccess;
    barrier.oldLayout = from;
    barrier.newLayout = to;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image.handle();
    barrier.subresourceRange = {image.aspect(), 0, image.desc().mipLevels, 0, image.layers()};
    VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.imageMemoryBarrierCount = 1;
    dependency.pImageMemoryBarriers = &barrier;
    vkCmdPipelineBarrier2(cmd, &dependency);
}

}  // namespace candela::render
