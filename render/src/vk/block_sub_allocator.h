#pragma once
// Places ranges inside one block of [0, size) bytes: first fit over an address-ordered free list,
// with neighbouring free ranges merged on free. No Vulkan here, so it is unit-tested without a
// device; MemoryAllocator runs one per VkDeviceMemory block.
//
// Why first fit is enough: the engine allocates mostly at load time (textures, meshes, targets)
// and frees rarely (resize, scene change), with tens to hundreds of ranges per block. A linear
// walk over the free ranges costs microseconds at that scale, and taking the lowest address that
// fits keeps the block's tail free for the next large request.
#include <cstdint>
#include <map>
#include <optional>

namespace candela::render {

// bufferImageGranularity separates "linear" resources (buffers, linear images) from optimally
// tiled images that share a page of a block; same-kind neighbours need no padding.
enum class ResourceTiling : uint8_t { Linear, Optimal };

class BlockSubAllocator {
public:
    // granularity: VkPhysicalDeviceLimits::bufferImageGranularity (a power of two, >= 1).
    BlockSubAllocator(uint64_t size, uint64_t granularity);

    // Offset of a new range of `size` bytes aligned to `alignment` (a power of two), or nothing
    // when no free range can hold it. A range never shares a granularity page with a neighbour
    // of the other tiling.
    std::optional<uint64_t> allocate(uint64_t size, uint64_t alignment, ResourceTiling tiling);
    // Returns the range that starts at `offset` (from allocate) to the free list.
    void free(uint64_t offset);

    uint64_t size() const { return size_; }
    uint64_t usedBytes() const { return usedBytes_; }
    bool empty() const { return allocations_.empty(); }
    size_t allocationCount() const { return allocations_.size(); }
    size_t freeRangeCount() const { return freeRanges_.size(); }
    uint64_t largestFreeRange() const;

private:
    struct Allocation {
        uint64_t size;
        ResourceTiling tiling;
    };
    // Where a request fits in the free range [begin, end), or nothing.
    std::optional<uint64_t> placeIn(uint64_t begin, uint64_t end, uint64_t size, uint64_t alignment,
                                    ResourceTiling tiling) const;
    bool conflictsOnPage(uint64_t lastByteOfFirst, uint64_t firstByteOfSecond) const;
    void addFreeRange(uint64_t offset, uint64_t size);

    uint64_t size_;
    uint64_t granularity_;
    uint64_t usedBytes_ = 0;
    std::map<uint64_t, uint64_t> freeRanges_;  // offset -> size; never adjacent to each other
    std::map<uint64_t, Allocation>
        allocations_;  // offset -> range; with freeRanges_ tiles [0,size)
};

}  // namespace candela::render
