#include "vk/sampler.h"

#include <utility>

#include "candela/render/gpu_context.h"
#include "vk/vk_check.h"

namespace candela::render {

Sampler::Sampler(GpuContext& context, const SamplerDesc& desc) : device_(context.device()) {
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = desc.filter;
    info.minFilter = desc.filter;
    info.mipmapMode =
        desc.mipmapped ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
    info.addressModeU = desc.addressU;
    info.addressModeV = desc.addressV;
    info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    info.maxLod = desc.mipmapped ? VK_LOD_CLAMP_NONE : 0.0f;
    info.compareEnable = desc.compare ? VK_TRUE : VK_FALSE;
    info.compareOp = desc.compareOp;
    CANDELA_VK_CHECK(vkCreateSampler(device_, &info, nullptr, &sampler_));
}

Sampler::~Sampler() {
    if (sampler_) vkDestroySampler(device_, sampler_, nullptr);
}

Sampler::Sampler(Sampler&& other) noexcept {
    *this = std::move(other);
}

Sampler& Sampler::operator=(Sampler&& other) noexcept {
    if (this != &other) {
        if (sampler_) vkDestroySampler(device_, sampler_, nullptr);
        device_ = std::exchange(other.device_, VK_NULL_HANDLE);
        sampler_ = std::exchange(other.sampler_, VK_NULL_HANDLE);
    }
    return *this;
}

}  // namespace candela::render
