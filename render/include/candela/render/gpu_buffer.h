#pragma once
// A VkBuffer with its own memory. Host-visible buffers stay mapped for their lifetime.
#include <vulkan/vulkan.h>

#include <cstddef>

namespace candela::render {

class GpuContext;

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
    void* mapped() const { return mapped_; }  // null for device-local buffers

private:
    void release();

    VkDevice device_ = VK_NULL_HANDLE;
    VkBuffer buffer_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkDeviceSize size_ = 0;
    void* mapped_ = nullptr;
};

}  // namespace candela::render
