// The renderer's frame-persistent targets (Renderer::createTargets and resize): the HDR and
// LDR images, the cleared TAA, GTAO and SSR histories and the light pair counts, and the
// temporal state that restarts with them.

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "candela/render/gpu_context.h"
#include "candela/render/renderer.h"
#include "clustered/cluster_light_lists.h"
#include "features/feature_list.h"
#include "lit_scene.h"
#include "passes/ambient_occlusion/ambient_occlusion_pass.h"
#include "passes/lighting/lighting_pass.h"
#include "passes/output/output_stage.h"
#include "passes/ssr/ssr_pass.h"
#include "vk/image_transfer.h"

namespace candela::render {

std::string Renderer::outputSizeProblem(const GpuContext& context, uint32_t width,
                                        uint32_t height) {
    const auto gib = [](uint64_t bytes) {
        char text[32];
        std::snprintf(text, sizeof(text), "%.1f GiB", double(bytes) / double(1ull << 30));
        return std::string(text);
    };
    const uint32_t largestSide = context.properties().limits.maxImageDimension2D;
    if (width > largestSide || height > largestSide) {
        return "this device's images are at most " + std::to_string(largestSide) +
               " pixels on a side";
    }
    const uint64_t pixels = uint64_t(width) * height;
    VkImageFormatProperties format{};
    if (vkGetPhysicalDeviceImageFormatProperties(
            context.physicalDevice(), VK_FORMAT_R32G32B32A32_SFLOAT, VK_IMAGE_TYPE_2D,
            VK_IMAGE_TILING_OPTIMAL,
            VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
            0, &format) == VK_SUCCESS &&
        pixels * 16 >= format.maxResourceSize) {
        return "its RGBA32F radiance target (" + gib(pixels * 16) +
               ") is past this device's largest image of that format (" +
               gib(format.maxResourceSize) + ")";
    }
    VkPhysicalDeviceMemoryProperties memory{};
    vkGetPhysicalDeviceMemoryProperties(context.physicalDevice(), &memory);
    VkDeviceSize largestHeap = 0;
    for (uint32_t h = 0; h < memory.memoryHeapCount; ++h) {
        if (memory.memoryHeaps[h].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT) {
            largestHeap = std::max(largestHeap, memory.memoryHeaps[h].size);
        }
    }
    if (largestHeap > 0 && pixels * kMinimumBytesPerPixel > largestHeap) {
        return "a frame's targets need at least " + gib(pixels * kMinimumBytesPerPixel) + " (" +
               std::to_string(kMinimumBytesPerPixel) +
               " bytes a pixel) and this device's largest memory heap holds " + gib(largestHeap);
    }
    return "";
}

void Renderer::resize(uint32_t width, uint32_t height) {
    targets_.outputWidth = width;
    targets_.outputHeight = height;
    targets_.width = scaledSize(width, options_.renderScale);
    targets_.height = scaledSize(height, options_.renderScale);
    createTargets();
}

void Renderer::createTargets() {
    Targets& t = targets_;
    // The upscale pass and its target exist exactly while the sizes differ (a 1-pixel side
    // may round to 1).
    output_->setUpscales(t.width != t.outputWidth || t.height != t.outputHeight);
    if (!output_->upscales()) t.outputHdr = GpuImage();
    // RGBA32F, not 16F: captures are compared at 1e-4..1e-5 relative, below half precision.
    // Transfer destination: TAA copies its resolve back into it.
    // Sampled: forward MSAA copies it into its multisampled target; the upscale pass filters it.
    t.hdr =
        GpuImage(context_, {VK_FORMAT_R32G32B32A32_SFLOAT, t.width, t.height, 1, false,
                            VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_STORAGE_BIT |
                                VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                                (options_.msaaSamples > 1 || output_->upscales()
                                     ? VkImageUsageFlags(VK_IMAGE_USAGE_SAMPLED_BIT)
                                     : 0u)});
    lit_->restart();
    // Colour attachment too: UI overlays (candela::ui) draw onto the tonemapped image.
    if (output_->upscales()) {
        // Written by the upscale pass, read by tonemapping, copied by captures.
        t.outputHdr = GpuImage(
            context_, {VK_FORMAT_R32G32B32A32_SFLOAT, t.outputWidth, t.outputHeight, 1, false,
                       VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                           VK_IMAGE_USAGE_TRANSFER_DST_BIT});
    }
    t.ldr = GpuImage(context_, {VK_FORMAT_R8G8B8A8_UNORM, t.outputWidth, t.outputHeight, 1, false,
                                VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                    VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT});
    // Cleared on the device each frame (lighting_counts_clear) before the atomics add to it.
    ensureHostBuffer(context_, t.pairCounts,
                     VkDeviceSize(LightingPass::workgroupCount(t.width, t.height)) *
                         LightingPass::kCountsPerWorkgroup * sizeof(uint32_t),
                     VK_BUFFER_USAGE_TRANSFER_DST_BIT);
}

void Renderer::restartTemporalHistory() {
    features_->restartHistories();
    lit_->restart();
}

}  // namespace candela::render
