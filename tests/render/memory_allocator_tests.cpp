// GpuBuffer and GpuImage memory from the context's MemoryAllocator, on the real device with
// validation required: small resources share blocks, large images get dedicated memory, freed
// blocks are returned, and every buffer keeps its own bytes.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "candela/render/gpu_buffer.h"
#include "candela/render/gpu_image.h"
#include "offscreen_frame.h"
#include "vk/memory_allocator.h"

using namespace candela::render;

namespace {
constexpr VkBufferUsageFlags kCopyUsage =
    VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;

void fill(const GpuBuffer& buffer, uint8_t value) {
    std::memset(buffer.mapped(), value, buffer.size());
}

bool holdsOnly(const GpuBuffer& buffer, uint8_t value) {
    const auto* bytes = static_cast<const uint8_t*>(buffer.mapped());
    for (VkDeviceSize i = 0; i < buffer.size(); ++i) {
        if (bytes[i] != value) return false;
    }
    return true;
}
}  // namespace

TEST(MemoryAllocator, SmallBuffersAndImagesShareBlocks) {
    GpuContext context(test::requiredValidation());
    const MemoryStatistics before = context.memoryStatistics();

    std::vector<GpuBuffer> buffers;
    VkDeviceSize bufferBytes = 0;
    for (uint32_t i = 0; i < 200; ++i) {
        const VkDeviceSize size = 256 + 64 * (i % 64);
        buffers.emplace_back(context, size, kCopyUsage, MemoryLocation::HostVisible);
        bufferBytes += size;
    }
    std::vector<GpuImage> images;
    for (uint32_t i = 0; i < 64; ++i) {
        images.emplace_back(context, ImageDesc{VK_FORMAT_R8G8B8A8_UNORM, 16 + i, 16, 1, false,
                                               VK_IMAGE_USAGE_SAMPLED_BIT});
    }

    const MemoryStatistics during = context.memoryStatistics();
    EXPECT_EQ(during.allocations - before.allocations, 264u);
    EXPECT_EQ(during.dedicatedAllocations, before.dedicatedAllocations);
    // 264 resources, a few hundred KiB in all: one first block per memory type in use.
    EXPECT_LE(during.blocks - before.blocks, 2u);
    EXPECT_GE(during.bytesUsed - before.bytesUsed, bufferBytes);
    EXPECT_LE(during.bytesUsed, during.bytesAllocated);

    buffers.clear();
    images.clear();
    const MemoryStatistics after = context.memoryStatistics();
    EXPECT_EQ(after.allocations, before.allocations);
    EXPECT_EQ(after.bytesUsed, before.bytesUsed);
    EXPECT_EQ(context.validationMessages(), 0u);
}

// Neighbouring sub-allocations must not alias: each mapping holds its own bytes, and a device
// copy between two of them lands at the destination's offset only.
TEST(MemoryAllocator, SubAllocatedBuffersKeepTheirOwnBytes) {
    GpuContext context(test::requiredValidation());
    std::vector<GpuBuffer> buffers;
    for (uint32_t i = 0; i < 16; ++i) {
        buffers.emplace_back(context, 1000 + i, kCopyUsage, MemoryLocation::HostVisible);
        fill(buffers.back(), static_cast<uint8_t>(i + 1));
    }
    for (uint32_t i = 0; i < 16; ++i)
        EXPECT_TRUE(holdsOnly(buffers[i], static_cast<uint8_t>(i + 1))) << "buffer " << i;

    context.submitAndWait([&](VkCommandBuffer cmd) {
        VkBufferCopy region{0, 0, buffers[3].size()};
        vkCmdCopyBuffer(cmd, buffers[3].handle(), buffers[7].handle(), 1, &region);
        VkMemoryBarrier2 toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
        toHost.srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT;
        toHost.srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT;
        toHost.dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT;
        toHost.dstAccessMask = VK_ACCESS_2_HOST_READ_BIT;
        VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
        dependency.memoryBarrierCount = 1;
        dependency.pMemoryBarriers = &toHost;
        vkCmdPipelineBarrier2(cmd, &dependency);
    });
    const auto* copied = static_cast<const uint8_t*>(buffers[7].mapped());
    for (VkDeviceSize i = 0; i < buffers[3].size(); ++i)
        ASSERT_EQ(copied[i], 4u) << "byte " << i;
    EXPECT_EQ(copied[buffers[3].size()], 8u);  // buffer 7 is 4 bytes longer than buffer 3
    EXPECT_TRUE(holdsOnly(buffers[6], 7));
    EXPECT_TRUE(holdsOnly(buffers[8], 9));
    EXPECT_EQ(context.validationMessages(), 0u);
}

TEST(MemoryAllocator, EmptyBlocksBeyondOnePerTypeAreReleased) {
    GpuContext context(test::requiredValidation());
    const MemoryStatistics before = context.memoryStatistics();
    std::vector<GpuBuffer> buffers;
    // 40 MiB of 1 MiB device buffers outgrow the first blocks (8, then 16, then 32 MiB).
    for (int i = 0; i < 40; ++i) {
        buffers.emplace_back(context, 1 << 20, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                             MemoryLocation::Device);
    }
    const MemoryStatistics during = context.memoryStatistics();
    EXPECT_GE(during.blocks - before.blocks, 3u);
    EXPECT_EQ(during.dedicatedAllocations, before.dedicatedAllocations);
    EXPECT_GE(during.bytesAllocated - before.bytesAllocated, VkDeviceSize(40) << 20);

    buffers.clear();
    const MemoryStatistics after = context.memoryStatistics();
    EXPECT_EQ(after.blocks, before.blocks + 1);  // one empty block stays for the next request
    EXPECT_EQ(after.bytesUsed, before.bytesUsed);
    EXPECT_LT(after.bytesAllocated, during.bytesAllocated);
    EXPECT_EQ(context.validationMessages(), 0u);
}

TEST(MemoryAllocator, LargeImagesGetDedicatedMemory) {
    GpuContext context(test::requiredValidation());
    const MemoryStatistics before = context.memoryStatistics();
    // 2048x2048 RGBA32F is 64 MiB: at least half of a 64 MiB block.
    {
        GpuImage large(context, ImageDesc{VK_FORMAT_R32G32B32A32_SFLOAT, 2048, 2048, 1, false,
                                          VK_IMAGE_USAGE_SAMPLED_BIT});
        GpuImage small(context, ImageDesc{VK_FORMAT_R32G32B32A32_SFLOAT, 64, 64, 1, false,
                                          VK_IMAGE_USAGE_SAMPLED_BIT});
        const MemoryStatistics during = context.memoryStatistics();
        EXPECT_EQ(during.dedicatedAllocations - before.dedicatedAllocations, 1u);
        EXPECT_EQ(during.allocations - before.allocations, 2u);
        EXPECT_GE(during.bytesUsed - before.bytesUsed, VkDeviceSize(64) << 20);
    }
    const MemoryStatistics after = context.memoryStatistics();
    EXPECT_EQ(after.dedicatedAllocations, before.dedicatedAllocations);
    EXPECT_EQ(after.bytesUsed, before.bytesUsed);
    EXPECT_EQ(context.validationMessages(), 0u);
}

TEST(MemoryAllocator, BlockSizesFollowTheHeap) {
    GpuContext context(test::requiredValidation());
    MemoryAllocator& allocator = context.memoryAllocator();
    VkPhysicalDeviceMemoryProperties memory;
    vkGetPhysicalDeviceMemoryProperties(context.physicalDevice(), &memory);
    for (uint32_t type = 0; type < memory.memoryTypeCount; ++type) {
        const VkDeviceSize heap = memory.memoryHeaps[memory.memoryTypes[type].heapIndex].size;
        const VkDeviceSize block = allocator.preferredBlockSize(type);
        EXPECT_LE(block, MemoryAllocator::kLargeHeapBlockSize);
        if (heap > (VkDeviceSize(1) << 30)) {
            EXPECT_EQ(block, MemoryAllocator::kLargeHeapBlockSize);
        } else {
            EXPECT_LE(block, heap / 8);
        }
    }
}
