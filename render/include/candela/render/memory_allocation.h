#pragma once
// A range of device memory handed out by the engine's allocator (render/src/vk/memory_allocator.h):
// a sub-range of a shared block, or a whole dedicated VkDeviceMemory for large resources.
#include <vulkan/vulkan.h>

#include <cstdint>

namespace candela::render {

struct MemoryAllocation {
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize offset = 0;  // where the resource is bound inside `memory`
    VkDeviceSize size = 0;
    void* mapped = nullptr;  // host pointer to `offset`, when host access was asked for
    uint32_t memoryType = 0;
    bool dedicated = false;  // owns `memory` alone

    explicit operator bool() const { return memory != VK_NULL_HANDLE; }
};

// What the allocator holds now, for --stats and tests.
struct MemoryStatistics {
    uint32_t blocks = 0;                // shared VkDeviceMemory blocks
    uint32_t dedicatedAllocations = 0;  // VkDeviceMemory objects owned by one resource
    uint32_t allocations = 0;           // live resources, shared and dedicated
    VkDeviceSize bytesAllocated = 0;    // obtained from Vulkan: blocks plus dedicated memory
    VkDeviceSize bytesUsed = 0;         // bound to live resources
};

}  // namespace candela::render
