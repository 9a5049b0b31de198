#pragma once
// A VkBuffer bound to a range of the context's MemoryAllocator. Host-visible buffers stay
// mapped for their lifetime.
#include <vulkan/vulkan.h>

#include <cstddef>

#include "candela/render/memory_allocation.h"

namespace candela::render {

class GpuContext;
class MemoryAllocator;

enum class MemoryLocation { Device, HostVisible };

class GpuBuffer {
public:
    GpuBuffer() = default;
    GpuBuffer(GpuContext& context, VkDeviceSize size, VkBufferUsageFlags usage,
              MemoryLocation location);
    ~GpuBuffer();
    GpuBuffer(GpuBuffer&& other) noexcept;
    GpuBuffer& operator=(GpuBuffer&& other) noexcept;
    GpuBuffer(const GpuBuffer&) = delete;
    GpuBuffer& operator=(const GpuBuffer&) = delete;

    VkBuffer handle() const { return buffer_; }
    VkDeviceSize size() const { return size_; }
    void* mapped() const { return memory_.mapped; }  // null for device-local buffers

private:
    void release();

    VkDevice device_ = VK_NULL_HANDLE;
    MemoryAllocator* allocator_ = nullptr;
    VkBuffer buffer_ = VK_NULL_HANDLE;
    MemoryAllocation memory_{};
    VkDeviceSize size_ = 0;
};

}  // namespace candela::render
