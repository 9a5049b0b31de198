#pragma once
// Whole-image copies between host memory and a GpuImage, every mip and layer in order
// (mip 0 layers 0..n, mip 1 ...), tightly packed: what the environment cache stores.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

namespace candela::render {

class GpuContext;
class GpuImage;

// Bytes of all mips and layers of `image` at `texelBytes` per texel.
uint64_t imageByteSize(const GpuImage& image, uint32_t texelBytes);

// Reads every mip and layer; the image is in `layout` before and after.
std::vector<uint8_t> readImage(GpuContext& context, const GpuImage& image, uint32_t texelBytes,
                               VkImageLayout layout);

// Writes every mip and layer from `bytes` (imageByteSize long); leaves the image in
// SHADER_READ_ONLY_OPTIMAL.
void writeImage(GpuContext& context, const GpuImage& image, uint32_t texelBytes,
                const uint8_t* bytes);

}  // namespace candela::render
