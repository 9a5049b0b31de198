#include "vk/image_transfer.h"

#include <algorithm>
#include <cstring>

#include "candela/render/gpu_buffer.h"
#include "candela/render/gpu_context.h"
#include "candela/render/gpu_image.h"

namespace candela::render {

namespace {

std::vector<VkBufferImageCopy> mipRegions(const GpuImage& image, uint32_t texelBytes) {
    std::vector<VkBufferImageCopy> regions;
    VkDeviceSize offset = 0;
    for (uint32_t mip = 0; mip < image.desc().mipLevels; ++mip) {
        uint32_t w = std::max(image.desc().width >> mip, 1u);
        uint32_t h = std::max(image.desc().height >> mip, 1u);
        VkBufferImageCopy region{};
        region.bufferOffset = offset;
        region.imageSubresource = {image.aspect(), mip, 0, image.layers()};
        region.imageExtent = {w, h, 1};
        regions.push_back(region);
        offset += VkDeviceSize(w) * h * texelBytes * image.layers();
    }
    return regions;
}

}  // namespace

uint64_t imageByteSize(const GpuImage& image, uint32_t texelBytes) {
    uint64_t bytes = 0;
    for (uint32_t mip = 0; mip < image.desc().mipLevels; ++mip) {
        bytes += uint64_t(std::max(image.desc().width >> mip, 1u)) *
                 std::max(image.desc().height >> mip, 1u) * texelBytes * image.layers();
    }
    return bytes;
}

std::vector<uint8_t> readImage(GpuContext& context, const GpuImage& image, uint32_t texelBytes,
                               VkImageLayout layout) {
    uint64_t bytes = imageByteSize(image, texelBytes);
    GpuBuffer staging(context, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                      MemoryLocation::HostVisible);
    std::vector<VkBufferImageCopy> regions = mipRegions(image, texelBytes);
    context.submitAndWait([&](VkCommandBuffer cmd) {
        transitionImage(cmd, image, layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                        VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT,
                        VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
        vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                               staging.handle(), uint32_t(regions.size()), regions.data());
        transitionImage(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, layout,
                        VK_PIPELINE_STAGE_2_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                        VK_ACCESS_2_MEMORY_READ_BIT);
    });
    std::vector<uint8_t> out(bytes);
    std::memcpy(out.data(), staging.mapped(), bytes);
    return out;
}

void writeImage(GpuContext& context, const GpuImage& image, uint32_t texelBytes,
                const uint8_t* bytes) {
    uint64_t size = imageByteSize(image, texelBytes);
    GpuBuffer staging(context, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryLocation::HostVisible);
    std::memcpy(staging.mapped(), bytes, size);
    std::vector<VkBufferImageCopy> regions = mipRegions(image, texelBytes);
    context.submitAndWait([&](VkCommandBuffer cmd) {
        transitionImage(cmd, image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                        VK_PIPELINE_STAGE_2_NONE, 0, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
                        VK_ACCESS_2_TRANSFER_WRITE_BIT);
        vkCmdCopyBufferToImage(cmd, staging.handle(), image.handle(),
                               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, uint32_t(regions.size()),
                               regions.data());
        transitionImage(
            cmd, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
            VK_ACCESS_2_TRANSFER_WRITE_BIT,
            VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
            VK_ACCESS_2_SHADER_READ_BIT);
    });
}

}  // namespace candela::render
