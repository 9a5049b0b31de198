#pragma once
// The forward pass's MSAA sample count (RendererOptions::msaaSamples, --msaa, the scene file's
// "msaa"), checked against what the device can render into the pass's targets.
#include <vulkan/vulkan.h>

#include <cstdint>

namespace candela::render {

class GpuContext;

// `requested` as a sample count: 1 (off), or 2, 4 or 8 when the device supports it for the
// HDR (RGBA32F), motion and depth targets. Anything else throws std::invalid_argument naming
// the value and the counts the device supports.
VkSampleCountFlagBits forwardMsaaSamples(const GpuContext& context, uint32_t requested);

}  // namespace candela::render
