#pragma once
// Non-owning views of the images and buffers a pass records with, whether the frame graph
// created them (transients in its pool) or imported them (a GpuImage or GpuBuffer).
#include <vulkan/vulkan.h>

#include "candela/render/gpu_buffer.h"
#include "candela/render/gpu_image.h"

namespace candela::render {

struct ImageRef {
    VkImage image = VK_NULL_HANDLE;
    VkImageView imageView = VK_NULL_HANDLE;
    ImageDesc description;

    ImageRef() = default;
    ImageRef(VkImage i, VkImageView v, const ImageDesc& d)
        : image(i), imageView(v), description(d) {}
    ImageRef(const GpuImage& gpu)  // NOLINT: a GpuImage is usable wherever a view is
        : image(gpu.handle()), imageView(gpu.view()), description(gpu.desc()) {}
    VkImage handle() const { return image; }
    VkImageView view() const { return imageView; }
    const ImageDesc& desc() const { return description; }
};

struct BufferRef {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceSize bytes = 0;
    void* hostPointer = nullptr;

    BufferRef() = default;
    BufferRef(VkBuffer b, VkDeviceSize s, void* m = nullptr)
        : buffer(b), bytes(s), hostPointer(m) {}
    BufferRef(const GpuBuffer& gpu)  // NOLINT
        : buffer(gpu.handle()), bytes(gpu.size()), hostPointer(gpu.mapped()) {}
    VkBuffer handle() const { return buffer; }
    VkDeviceSize size() const { return bytes; }
    void* mapped() const { return hostPointer; }
};

}  // namespace candela::render
