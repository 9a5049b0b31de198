#include "candela/render/gpu_buffer.h"

#include <utility>

#include "candela/render/gpu_context.h"
#include "vk/memory_allocator.h"
#include "vk/vk_check.h"

namespace candela::render {

GpuBuffer::GpuBuffer(GpuContext& context, VkDeviceSize size, VkBufferUsageFlags usage,
                     MemoryLocation location)
    : device_(context.device()), allocator_(&context.memoryAllocator()), size_(size) {
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    CANDELA_VK_CHECK(vkCreateBuffer(device_, &info, nullptr, &buffer_));

    // Host-coherent so CPU writes and GPU readbacks need no explicit flush/invalidate.
    const bool hostVisible = location == MemoryLocation::HostVisible;
    const VkMemoryPropertyFlags flags =
        hostVisible ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT
                    : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    try {
        memory_ = allocator_->allocateFor(buffer_, flags, hostVisible);
        CANDELA_VK_CHECK(vkBindBufferMemory(device_, buffer_, memory_.memory, memory_.offset));
    } catch (...) {
        release();
        throw;
    }
}

GpuBuffer::~GpuBuffer() {
    release();
}

GpuBuffer::GpuBuffer(GpuBuffer&& other) noexcept {
    *this = std::move(other);
}

GpuBuffer& GpuBuffer::operator=(GpuBuffer&& other) noexcept {
    if (this != &other) {
        release();
        device_ = std::exchange(other.device_, VK_NULL_HANDLE);
        allocator_ = std::exchange(other.allocator_, nullptr);
        buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
        memory_ = std::exchange(other.memory_, MemoryAllocation{});
        size_ = std::exchange(other.size_, 0);
    }
    return *this;
}

void GpuBuffer::release() {
    if (!device_) return;
    if (buffer_) vkDestroyBuffer(device_, buffer_, nullptr);
    allocator_->free(memory_);
    buffer_ = VK_NULL_HANDLE;
    memory_ = {};
}

}  // namespace candela::render
