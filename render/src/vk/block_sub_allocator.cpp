#include "vk/block_sub_allocator.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace candela::render {

namespace {
uint64_t alignUp(uint64_t value, uint64_t alignment) {
    return (value + alignment - 1) & ~(alignment - 1);
}
bool isPowerOfTwo(uint64_t value) {
    return value != 0 && (value & (value - 1)) == 0;
}
}  // namespace

BlockSubAllocator::BlockSubAllocator(uint64_t size, uint64_t granularity)
    : size_(size), granularity_(std::max<uint64_t>(granularity, 1)) {
    if (!isPowerOfTwo(granularity_)) {
        throw std::invalid_argument("BlockSubAllocator: granularity " +
                                    std::to_string(granularity) + " is not a power of two");
    }
    if (size_ > 0) freeRanges_.emplace(0, size_);
}

bool BlockSubAllocator::conflictsOnPage(uint64_t lastByteOfFirst,
                                        uint64_t firstByteOfSecond) const {
    return lastByteOfFirst / granularity_ == firstByteOfSecond / granularity_;
}

std::optional<uint64_t> BlockSubAllocator::placeIn(uint64_t begin, uint64_t end, uint64_t size,
                                                   uint64_t alignment,
                                                   ResourceTiling tiling) const {
    uint64_t offset = alignUp(begin, alignment);
    // Free ranges are never adjacent, so the allocation before this range ends exactly at begin.
    if (begin > 0) {
        auto previous = std::prev(allocations_.lower_bound(begin));
        if (previous->second.tiling != tiling && conflictsOnPage(begin - 1, offset)) {
            offset = alignUp(offset, granularity_);
        }
    }
    if (offset < begin || offset > end || end - offset < size) return std::nullopt;
    // ...and the allocation after it starts exactly at end.
    if (end < size_) {
        const Allocation& next = allocations_.at(end);
        if (next.tiling != tiling && conflictsOnPage(offset + size - 1, end)) return std::nullopt;
    }
    return offset;
}

std::optional<uint64_t> BlockSubAllocator::allocate(uint64_t size, uint64_t alignment,
                                                    ResourceTiling tiling) {
    if (size == 0) throw std::invalid_argument("BlockSubAllocator: zero-sized allocation");
    alignment = std::max<uint64_t>(alignment, 1);
    if (!isPowerOfTwo(alignment)) {
        throw std::invalid_argument("BlockSubAllocator: alignment " + std::to_string(alignment) +
                                    " is not a power of two");
    }
    for (auto range = freeRanges_.begin(); range != freeRanges_.end(); ++range) {
        const uint64_t begin = range->first;
        const uint64_t end = begin + range->second;
        std::optional<uint64_t> offset = placeIn(begin, end, size, alignment, tiling);
        if (!offset) continue;
        // Split the free range: padding before and the remainder after stay free.
        freeRanges_.erase(range);
        if (*offset > begin) freeRanges_.emplace(begin, *offset - begin);
        if (*offset + size < end) freeRanges_.emplace(*offset + size, end - (*offset + size));
        allocations_.emplace(*offset, Allocation{size, tiling});
        usedBytes_ += size;
        return offset;
    }
    return std::nullopt;
}

void BlockSubAllocator::free(uint64_t offset) {
    auto found = allocations_.find(offset);
    if (found == allocations_.end()) {
        throw std::invalid_argument("BlockSubAllocator: no allocation at offset " +
                                    std::to_string(offset));
    }
    const uint64_t size = found->second.size;
    allocations_.erase(found);
    usedBytes_ -= size;
    addFreeRange(offset, size);
}

void BlockSubAllocator::addFreeRange(uint64_t offset, uint64_t size) {
    // Padding left by alignment is free already, so the freed range may touch free ranges on
    // either side: merge them so the list stays non-adjacent (the invariant placeIn relies on).
    auto next = freeRanges_.lower_bound(offset);
    if (next != freeRanges_.begin()) {
        auto previous = std::prev(next);
        if (previous->first + previous->second == offset) {
            offset = previous->first;
            size += previous->second;
            freeRanges_.erase(previous);
        }
    }
    if (next != freeRanges_.end() && offset + size == next->first) {
        size += next->second;
        freeRanges_.erase(next);
    }
    freeRanges_.emplace(offset, size);
}

uint64_t BlockSubAllocator::largestFreeRange() const {
    uint64_t largest = 0;
    for (const auto& [offset, size] : freeRanges_)
        largest = std::max(largest, size);
    return largest;
}

}  // namespace candela::render
