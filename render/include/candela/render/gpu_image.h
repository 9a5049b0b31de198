#pragma once
// A 2D (or cube) VkImage bound to a range of the context's MemoryAllocator, with one view over
// all mips and layers.
#include <vulkan/vulkan.h>

#include <cstdint>

#include "candela/render/memory_allocation.h"

namespace candela::render {

class GpuContext;
class MemoryAllocator;

struct ImageDesc {
    VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
    uint32_t width = 1;
    uint32_t height = 1;
    uint32_t mipLevels = 1;
    bool cube = false;
    VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;  // >1: a multisampled target
};

class GpuImage {
public:
    GpuImage() = default;
    GpuImage(GpuContext& context, const ImageDesc& desc);
    ~GpuImage();
    GpuImage(GpuImage&& other) noexcept;
    GpuImage& operator=(GpuImage&& other) noexcept;
    GpuImage(const GpuImage&) = delete;
    GpuImage& operator=(const GpuImage&) = delete;

    VkImage handle() const { return image_; }
    VkImageView view() const { return view_; }
    const ImageDesc& desc() const { return desc_; }
    VkImageAspectFlags aspect() const;
    uint32_t layers() const { return desc_.cube ? 6u : 1u; }

private:
    void release();

    VkDevice device_ = VK_NULL_HANDLE;
    MemoryAllocator* allocator_ = nullptr;
    VkImage image_ = VK_NULL_HANDLE;
    VkImageView view_ = VK_NULL_HANDLE;
    MemoryAllocation memory_{};
    ImageDesc desc_{};
};

// Whole-image layout transition with synchronization2 stage/access masks.
void transitionImage(VkCommandBuffer cmd, const GpuImage& image, VkImageLayout from,
                     VkImageLayout to, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                     VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess);

}  // namespace candela::render
