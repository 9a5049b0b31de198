// Range placement inside one memory block, without a device: alignment, bufferImageGranularity,
// coalescing, fragmentation, exhaustion and freeing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <random>
#include <stdexcept>

#include "vk/block_sub_allocator.h"

using candela::render::BlockSubAllocator;
using candela::render::ResourceTiling;

namespace {
constexpr ResourceTiling kBuffer = ResourceTiling::Linear;
constexpr ResourceTiling kImage = ResourceTiling::Optimal;
}  // namespace

TEST(BlockSubAllocator, AlignsOffsetsAndReusesThePaddingForLaterRequests) {
    BlockSubAllocator block(4096, 1);
    EXPECT_EQ(block.allocate(100, 1, kBuffer), 0u);
    EXPECT_EQ(block.allocate(64, 256, kBuffer), 256u);  // 100..255 left free as padding
    EXPECT_EQ(block.allocate(50, 4, kBuffer), 100u);    // first fit finds the padding
    EXPECT_EQ(block.allocate(8, 8, kBuffer), 152u);     // 150 rounded up to 8
    EXPECT_EQ(block.usedBytes(), 100u + 64u + 50u + 8u);
    EXPECT_EQ(block.allocationCount(), 4u);
}

TEST(BlockSubAllocator, ExhaustionFailsUntilARangeIsFreed) {
    BlockSubAllocator block(1024, 1);
    EXPECT_EQ(block.allocate(2048, 1, kBuffer), std::nullopt);  // larger than the block
    EXPECT_EQ(block.allocate(1024, 1, kBuffer), 0u);
    EXPECT_EQ(block.allocate(1, 1, kBuffer), std::nullopt);
    EXPECT_EQ(block.largestFreeRange(), 0u);
    block.free(0);
    EXPECT_TRUE(block.empty());
    EXPECT_EQ(block.allocate(1, 1, kBuffer), 0u);
}

TEST(BlockSubAllocator, AlignmentPaddingCanExhaustABlock) {
    BlockSubAllocator block(1024, 1);
    EXPECT_EQ(block.allocate(600, 1, kBuffer), 0u);
    // 424 bytes are free, but at 512-byte alignment the range would start at 1024.
    EXPECT_EQ(block.allocate(400, 512, kBuffer), std::nullopt);
    EXPECT_EQ(block.allocate(400, 8, kBuffer), 600u);
}

TEST(BlockSubAllocator, FreeingNeighboursCoalescesIntoOneRange) {
    BlockSubAllocator block(1024, 1);
    for (uint64_t i = 0; i < 4; ++i)
        EXPECT_EQ(block.allocate(256, 256, kBuffer), i * 256);
    block.free(256);
    block.free(512);
    EXPECT_EQ(block.freeRangeCount(), 1u);
    EXPECT_EQ(block.largestFreeRange(), 512u);
    EXPECT_EQ(block.allocate(512, 1, kBuffer), 256u);
    block.free(0);
    block.free(768);
    block.free(256);
    EXPECT_TRUE(block.empty());
    EXPECT_EQ(block.usedBytes(), 0u);
    EXPECT_EQ(block.freeRangeCount(), 1u);
    EXPECT_EQ(block.largestFreeRange(), 1024u);
}

TEST(BlockSubAllocator, FragmentedFreeSpaceDoesNotHoldALargerRange) {
    BlockSubAllocator block(1024, 1);
    for (uint64_t i = 0; i < 8; ++i)
        ASSERT_EQ(block.allocate(128, 1, kBuffer), i * 128);
    for (uint64_t i = 0; i < 8; i += 2)
        block.free(i * 128);
    EXPECT_EQ(block.freeRangeCount(), 4u);
    EXPECT_EQ(block.usedBytes(), 512u);
    EXPECT_EQ(block.largestFreeRange(), 128u);
    EXPECT_EQ(block.allocate(256, 1, kBuffer), std::nullopt);  // 512 free, but in pieces
    block.free(384);  // joins 256..383, 384..511 and 512..639
    EXPECT_EQ(block.freeRangeCount(), 3u);
    EXPECT_EQ(block.allocate(256, 1, kBuffer), 256u);
}

TEST(BlockSubAllocator, ImageAfterABufferStartsOnTheNextGranularityPage) {
    BlockSubAllocator block(8192, 1024);
    EXPECT_EQ(block.allocate(100, 4, kBuffer), 0u);
    EXPECT_EQ(block.allocate(100, 16, kImage), 1024u);  // not 112: page 0 holds a buffer
    // Buffers still pack into page 0 behind the first buffer: the image is on another page.
    EXPECT_EQ(block.allocate(100, 16, kBuffer), 112u);
    // An image cannot use the rest of page 0 either; it goes right behind the first image.
    EXPECT_EQ(block.allocate(100, 16, kImage), 1136u);
}

TEST(BlockSubAllocator, BufferIsNotPlacedOnThePageOfAFollowingImage) {
    BlockSubAllocator block(4096, 256);
    EXPECT_EQ(block.allocate(100, 1, kImage), 0u);
    EXPECT_EQ(block.allocate(100, 16, kImage), 112u);  // same tiling: no padding
    block.free(0);
    // 0..111 is free but ends on the page of the image at 112: a buffer there would share it.
    EXPECT_EQ(block.allocate(16, 16, kBuffer), 256u);  // and after the image, page 1
    EXPECT_EQ(block.allocate(16, 16, kImage), 0u);     // an image may use the hole
}

TEST(BlockSubAllocator, GranularityOfOneMixesBuffersAndImagesTightly) {
    BlockSubAllocator block(1024, 1);
    EXPECT_EQ(block.allocate(100, 4, kBuffer), 0u);
    EXPECT_EQ(block.allocate(100, 4, kImage), 100u);
    EXPECT_EQ(block.allocate(100, 4, kBuffer), 200u);
}

TEST(BlockSubAllocator, RejectsBadRequests) {
    BlockSubAllocator block(1024, 1);
    EXPECT_THROW(block.allocate(0, 1, kBuffer), std::invalid_argument);
    EXPECT_THROW(block.allocate(16, 3, kBuffer), std::invalid_argument);
    EXPECT_THROW(block.free(0), std::invalid_argument);  // nothing allocated there
    EXPECT_THROW(BlockSubAllocator(1024, 3), std::invalid_argument);
}

// Random allocate/free traffic: live ranges never overlap, keep their alignment and the
// granularity rule, the byte count matches, and freeing everything leaves one whole range.
TEST(BlockSubAllocator, RandomTrafficKeepsRangesDisjointAndCoalescesBack) {
    constexpr uint64_t kSize = 1 << 20;
    constexpr uint64_t kGranularity = 1024;
    BlockSubAllocator block(kSize, kGranularity);
    struct Live {
        uint64_t size;
        uint64_t alignment;
        ResourceTiling tiling;
    };
    std::map<uint64_t, Live> live;
    std::mt19937 random(1234);
    uint64_t placed = 0;
    uint64_t refused = 0;
    for (int step = 0; step < 20000; ++step) {
        const bool doFree = !live.empty() && (random() % 100) < 45;
        if (doFree) {
            auto victim = live.begin();
            std::advance(victim, random() % live.size());
            block.free(victim->first);
            live.erase(victim);
        } else {
            const uint64_t size = 1 + random() % 8192;
            const uint64_t alignment = uint64_t(1) << (random() % 10);
            const ResourceTiling tiling = (random() % 2) ? kBuffer : kImage;
            std::optional<uint64_t> offset = block.allocate(size, alignment, tiling);
            if (!offset) {
                ++refused;
                continue;
            }
            ++placed;
            ASSERT_EQ(*offset % alignment, 0u);
            ASSERT_LE(*offset + size, kSize);
            ASSERT_TRUE(live.emplace(*offset, Live{size, alignment, tiling}).second);
        }
        uint64_t used = 0;
        const std::pair<const uint64_t, Live>* previous = nullptr;
        for (const auto& entry : live) {
            used += entry.second.size;
            if (previous) {
                const uint64_t previousEnd = previous->first + previous->second.size;
                ASSERT_LE(previousEnd, entry.first) << "overlap at step " << step;
                if (previous->second.tiling != entry.second.tiling) {
                    ASSERT_NE((previousEnd - 1) / kGranularity, entry.first / kGranularity)
                        << "buffer and image share a granularity page at step " << step;
                }
            }
            previous = &entry;
        }
        ASSERT_EQ(block.usedBytes(), used);
        ASSERT_EQ(block.allocationCount(), live.size());
    }
    EXPECT_GT(placed, 1000u);
    EXPECT_GT(refused, 0u);  // the traffic did fill the block at times
    for (const auto& entry : live)
        block.free(entry.first);
    EXPECT_TRUE(block.empty());
    EXPECT_EQ(block.freeRangeCount(), 1u);
    EXPECT_EQ(block.largestFreeRange(), kSize);
}
