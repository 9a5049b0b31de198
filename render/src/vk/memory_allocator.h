#pragma once
// Device memory for GpuBuffer and GpuImage: one VkDeviceMemory block holds many resources, so the
// engine stays far below maxMemoryAllocationCount and avoids the per-allocation cost of drivers.
//  - Blocks are per memory type. The first block of a type is an eighth of the preferred size
//    (64 MiB, or an eighth of a heap of 1 GiB or less) and each further block doubles up to it,
//    so small scenes stay small.
//  - Inside a block, BlockSubAllocator places ranges with the resource's alignment and keeps
//    buffers and optimal images apart by bufferImageGranularity.
//  - A resource gets its own VkDeviceMemory ("dedicated") only when the driver requires it, when
//    it prefers it for a resource of at least 1 MiB, or when the resource takes half a block or
//    more. Smaller dedicated allocations are what the validation layer's best-practices checks
//    flag, and large ones would waste most of a block.
//  - Host-visible blocks are mapped once, when the first host-accessed range lands in them, and
//    stay mapped; allocations get a pointer into that mapping.
//  - Freeing returns the range; a block left empty is released unless it is the only empty one of
//    its memory type (kept so a resize does not free and reallocate a block every frame).
// Thread safety: allocate, free and statistics take one mutex. Today resources are created on the
// thread that owns the GpuContext, but loaders and scheduler systems may create them in parallel.
#include <vulkan/vulkan.h>

#include <memory>
#include <mutex>
#include <vector>

#include "candela/render/memory_allocation.h"
#include "vk/block_sub_allocator.h"

namespace candela::render {

class MemoryAllocator {
public:
    MemoryAllocator(VkPhysicalDevice physicalDevice, VkDevice device);
    ~MemoryAllocator();
    MemoryAllocator(const MemoryAllocator&) = delete;
    MemoryAllocator& operator=(const MemoryAllocator&) = delete;

    // Memory for `buffer`, bound by the caller at allocation.offset. hostAccess maps it.
    MemoryAllocation allocateFor(VkBuffer buffer, VkMemoryPropertyFlags required, bool hostAccess);
    // Memory for an optimally tiled `image` (what GpuImage creates), device access only.
    MemoryAllocation allocateFor(VkImage image, VkMemoryPropertyFlags required);
    // Returns the range (or the dedicated memory); the resource must be destroyed already or
    // no longer in use by the device.
    void free(const MemoryAllocation& allocation);

    MemoryStatistics statistics() const;

    // The first memory type allowed by typeBits that has all `required` flags.
    uint32_t findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags required) const;
    // The size blocks of this memory type grow to; resources of half of it or more are dedicated.
    VkDeviceSize preferredBlockSize(uint32_t memoryType) const;

    static constexpr VkDeviceSize kLargeHeapBlockSize = 64ull << 20;
    static constexpr VkDeviceSize kMinPreferredDedicatedSize = 1ull << 20;

private:
    struct Block {
        VkDeviceMemory memory = VK_NULL_HANDLE;
        BlockSubAllocator ranges;
        void* mapped = nullptr;
    };
    struct Request {
        VkMemoryRequirements requirements{};
        bool prefersDedicated = false;
        bool requiresDedicated = false;
        VkBuffer buffer = VK_NULL_HANDLE;  // the dedicated owner, one of the two
        VkImage image = VK_NULL_HANDLE;
        ResourceTiling tiling = ResourceTiling::Linear;
        VkMemoryPropertyFlags required = 0;
        bool hostAccess = false;
    };

    MemoryAllocation allocate(const Request& request);
    MemoryAllocation allocateDedicated(const Request& request, uint32_t memoryType);
    Block& createBlock(uint32_t memoryType, VkDeviceSize minimumSize);
    void* mapBlock(Block& block);
    void releaseEmptyBlocks(uint32_t memoryType);

    VkDevice device_;
    VkPhysicalDeviceMemoryProperties memoryProperties_{};
    VkDeviceSize bufferImageGranularity_ = 1;
    mutable std::mutex mutex_;
    std::vector<std::vector<std::unique_ptr<Block>>> blocksByType_;
    uint32_t dedicatedAllocations_ = 0;
    VkDeviceSize dedicatedBytes_ = 0;
};

}  // namespace candela::render
