#include "vk/memory_allocator.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "vk/vk_check.h"

namespace candela::render {

namespace {
// Heaps this small (integrated GPUs' device-local carve-outs, host-visible BAR windows) get blocks
// of an eighth of the heap instead of 64 MiB.
constexpr VkDeviceSize kSmallHeapSize = 1ull << 30;
// Below this the best-practices layer flags an allocation as too small; no block is smaller.
constexpr VkDeviceSize kMinBlockSize = 1ull << 20;
// First block of a type is preferred >> 3, then >> 2, >> 1, then preferred.
constexpr uint32_t kFirstBlockShift = 3;
}  // namespace

MemoryAllocator::MemoryAllocator(VkPhysicalDevice physicalDevice, VkDevice device)
    : device_(device) {
    vkGetPhysicalDeviceMemoryProperties(physicalDevice, &memoryProperties_);
    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(physicalDevice, &properties);
    bufferImageGranularity_ = std::max<VkDeviceSize>(properties.limits.bufferImageGranularity, 1);
    blocksByType_.resize(memoryProperties_.memoryTypeCount);
}

MemoryAllocator::~MemoryAllocator() {
    // Resources still alive here outlived the device's users; their memory goes with the blocks.
    for (auto& blocks : blocksByType_) {
        for (auto& block : blocks)
            vkFreeMemory(device_, block->memory, nullptr);
    }
}

uint32_t MemoryAllocator::findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags required) const {
    for (uint32_t i = 0; i < memoryProperties_.memoryTypeCount; ++i) {
        bool allowed = (typeBits & (1u << i)) != 0;
        if (allowed && (memoryProperties_.memoryTypes[i].propertyFlags & required) == required) {
            return i;
        }
    }
    throw std::runtime_error("no Vulkan memory type with the required properties");
}

VkDeviceSize MemoryAllocator::preferredBlockSize(uint32_t memoryType) const {
    const uint32_t heap = memoryProperties_.memoryTypes[memoryType].heapIndex;
    const VkDeviceSize heapSize = memoryProperties_.memoryHeaps[heap].size;
    if (heapSize > kSmallHeapSize) return kLargeHeapBlockSize;
    return std::max(kMinBlockSize, (heapSize / 8) & ~VkDeviceSize(255));
}

MemoryAllocation MemoryAllocator::allocateFor(VkBuffer buffer, VkMemoryPropertyFlags required,
                                              bool hostAccess) {
    VkBufferMemoryRequirementsInfo2 info{VK_STRUCTURE_TYPE_BUFFER_MEMORY_REQUIREMENTS_INFO_2};
    info.buffer = buffer;
    VkMemoryDedicatedRequirements dedicated{VK_STRUCTURE_TYPE_MEMORY_DEDICATED_REQUIREMENTS};
    VkMemoryRequirements2 requirements{VK_STRUCTURE_TYPE_MEMORY_REQUIREMENTS_2};
    requirements.pNext = &dedicated;
    vkGetBufferMemoryRequirements2(device_, &info, &requirements);

    Request request;
    request.requirements = requirements.memoryRequirements;
    request.prefersDedicated = dedicated.prefersDedicatedAllocation;
    request.requiresDedicated = dedicated.requiresDedicatedAllocation;
    request.buffer = buffer;
    request.tiling = ResourceTiling::Linear;
    request.required = required;
    request.hostAccess = hostAccess;
    return allocate(request);
}

MemoryAllocation MemoryAllocator::allocateFor(VkImage image, VkMemoryPropertyFlags required) {
    VkImageMemoryRequirementsInfo2 info{VK_STRUCTURE_TYPE_IMAGE_MEMORY_REQUIREMENTS_INFO_2};
    info.image = image;
    VkMemoryDedicatedRequirements dedicated{VK_STRUCTURE_TYPE_MEMORY_DEDICATED_REQUIREMENTS};
    VkMemoryRequirements2 requirements{VK_STRUCTURE_TYPE_MEMORY_REQUIREMENTS_2};
    requirements.pNext = &dedicated;
    vkGetImageMemoryRequirements2(device_, &info, &requirements);

    Request request;
    request.requirements = requirements.memoryRequirements;
    request.prefersDedicated = dedicated.prefersDedicatedAllocation;
    request.requiresDedicated = dedicated.requiresDedicatedAllocation;
    request.image = image;
    request.tiling = ResourceTiling::Optimal;
    request.required = required;
    return allocate(request);
}

MemoryAllocation MemoryAllocator::allocate(const Request& request) {
    const VkMemoryPropertyFlags required =
        request.required | (request.hostAccess ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT : 0);
    const uint32_t memoryType = findMemoryType(request.requirements.memoryTypeBits, required);
    const VkDeviceSize size = request.requirements.size;

    std::lock_guard lock(mutex_);
    const bool dedicated = request.requiresDedicated ||
                           (request.prefersDedicated && size >= kMinPreferredDedicatedSize) ||
                           size >= preferredBlockSize(memoryType) / 2;
    if (dedicated) return allocateDedicated(request, memoryType);

    Block* target = nullptr;
    std::optional<VkDeviceSize> offset;
    for (auto& block : blocksByType_[memoryType]) {
        offset = block->ranges.allocate(size, request.requirements.alignment, request.tiling);
        if (offset) {
            target = block.get();
            break;
        }
    }
    if (!target) {
        target = &createBlock(memoryType, size);
        offset = target->ranges.allocate(size, request.requirements.alignment, request.tiling);
        // An empty block of at least `size` bytes always fits: offset 0 meets any alignment.
        if (!offset) throw std::logic_error("MemoryAllocator: a fresh block refused a range");
    }

    MemoryAllocation allocation;
    allocation.memory = target->memory;
    allocation.offset = *offset;
    allocation.size = size;
    allocation.memoryType = memoryType;
    if (request.hostAccess) allocation.mapped = static_cast<char*>(mapBlock(*target)) + *offset;
    return allocation;
}

MemoryAllocation MemoryAllocator::allocateDedicated(const Request& request, uint32_t memoryType) {
    VkMemoryDedicatedAllocateInfo dedicatedInfo{VK_STRUCTURE_TYPE_MEMORY_DEDICATED_ALLOCATE_INFO};
    dedicatedInfo.buffer = request.buffer;
    dedicatedInfo.image = request.image;
    VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    info.pNext = &dedicatedInfo;
    info.allocationSize = request.requirements.size;
    info.memoryTypeIndex = memoryType;

    MemoryAllocation allocation;
    CANDELA_VK_CHECK(vkAllocateMemory(device_, &info, nullptr, &allocation.memory));
    allocation.size = request.requirements.size;
    allocation.memoryType = memoryType;
    allocation.dedicated = true;
    if (request.hostAccess) {
        VkResult mapped =
            vkMapMemory(device_, allocation.memory, 0, VK_WHOLE_SIZE, 0, &allocation.mapped);
        if (mapped != VK_SUCCESS) {
            vkFreeMemory(device_, allocation.memory, nullptr);
            throwVkError("vkMapMemory (dedicated allocation)", mapped);
        }
    }
    ++dedicatedAllocations_;
    dedicatedBytes_ += allocation.size;
    return allocation;
}

MemoryAllocator::Block& MemoryAllocator::createBlock(uint32_t memoryType,
                                                     VkDeviceSize minimumSize) {
    auto& blocks = blocksByType_[memoryType];
    const VkDeviceSize preferred = preferredBlockSize(memoryType);
    const uint32_t shift =
        kFirstBlockShift -
        std::min<uint32_t>(kFirstBlockShift, static_cast<uint32_t>(blocks.size()));
    VkDeviceSize size = std::max(kMinBlockSize, preferred >> shift);
    while (size < minimumSize)
        size *= 2;

    VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    info.memoryTypeIndex = memoryType;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkResult result = VK_ERROR_OUT_OF_DEVICE_MEMORY;
    // When the heap is nearly full a smaller block may still fit the request.
    for (; size >= minimumSize; size /= 2) {
        info.allocationSize = size;
        result = vkAllocateMemory(device_, &info, nullptr, &memory);
        if (result == VK_SUCCESS || size / 2 < kMinBlockSize) break;
    }
    if (result != VK_SUCCESS) {
        throwVkError(
            ("vkAllocateMemory (block of memory type " + std::to_string(memoryType) + ")").c_str(),
            result);
    }
    blocks.push_back(std::make_unique<Block>(
        Block{memory, BlockSubAllocator(info.allocationSize, bufferImageGranularity_), nullptr}));
    return *blocks.back();
}

void* MemoryAllocator::mapBlock(Block& block) {
    if (!block.mapped) {
        CANDELA_VK_CHECK(vkMapMemory(device_, block.memory, 0, VK_WHOLE_SIZE, 0, &block.mapped));
    }
    return block.mapped;
}

void MemoryAllocator::free(const MemoryAllocation& allocation) {
    if (!allocation) return;
    std::lock_guard lock(mutex_);
    if (allocation.dedicated) {
        vkFreeMemory(device_, allocation.memory, nullptr);  // unmaps implicitly
        --dedicatedAllocations_;
        dedicatedBytes_ -= allocation.size;
        return;
    }
    auto& blocks = blocksByType_.at(allocation.memoryType);
    auto owner = std::find_if(blocks.begin(), blocks.end(), [&](const auto& block) {
        return block->memory == allocation.memory;
    });
    if (owner == blocks.end()) {
        throw std::logic_error(
            "MemoryAllocator::free: memory is not one of this allocator's blocks");
    }
    (*owner)->ranges.free(allocation.offset);
    if ((*owner)->ranges.empty()) releaseEmptyBlocks(allocation.memoryType);
}

void MemoryAllocator::releaseEmptyBlocks(uint32_t memoryType) {
    auto& blocks = blocksByType_[memoryType];
    bool keptOne = false;
    // Keep the largest empty block: it serves the most requests without a new allocation.
    std::stable_sort(blocks.begin(), blocks.end(), [](const auto& a, const auto& b) {
        return a->ranges.size() > b->ranges.size();
    });
    std::erase_if(blocks, [&](const std::unique_ptr<Block>& block) {
        if (!block->ranges.empty()) return false;
        if (!keptOne) {
            keptOne = true;
            return false;
        }
        vkFreeMemory(device_, block->memory, nullptr);
        return true;
    });
}

MemoryStatistics MemoryAllocator::statistics() const {
    std::lock_guard lock(mutex_);
    MemoryStatistics stats;
    stats.dedicatedAllocations = dedicatedAllocations_;
    stats.allocations = dedicatedAllocations_;
    stats.bytesAllocated = dedicatedBytes_;
    stats.bytesUsed = dedicatedBytes_;
    for (const auto& blocks : blocksByType_) {
        for (const auto& block : blocks) {
            ++stats.blocks;
            stats.allocations += static_cast<uint32_t>(block->ranges.allocationCount());
            stats.bytesAllocated += block->ranges.size();
            stats.bytesUsed += block->ranges.usedBytes();
        }
    }
    return stats;
}

}  // namespace candela::render
