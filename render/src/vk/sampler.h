#pragma once
// An owned VkSampler. Linear filtering with clamped or repeating addressing covers what the
// passes sample; mipmapped samplers filter between mips (trilinear).
#include <vulkan/vulkan.h>

namespace candela::render {

class GpuContext;

struct SamplerDesc {
    VkFilter filter = VK_FILTER_LINEAR;
    bool mipmapped = false;
    VkSamplerAddressMode addressU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    VkSamplerAddressMode addressV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    // Depth comparison (sampler2DShadow): returns reference `compareOp` texel, filtered.
    bool compare = false;
    VkCompareOp compareOp = VK_COMPARE_OP_ALWAYS;
};

class Sampler {
public:
    Sampler() = default;
    Sampler(GpuContext& context, const SamplerDesc& desc);
    ~Sampler();
    Sampler(Sampler&& other) noexcept;
    Sampler& operator=(Sampler&& other) noexcept;
    Sampler(const Sampler&) = delete;
    Sampler& operator=(const Sampler&) = delete;

    VkSampler handle() const { return sampler_; }

private:
    VkDevice device_ = VK_NULL_HANDLE;
    VkSampler sampler_ = VK_NULL_HANDLE;
};

}  // namespace candela::render
