#pragma once
// What a pass that samples the shadow maps binds (ShadowPass::descriptors).
#include <vulkan/vulkan.h>

namespace candela::render {

// What the shading passes bind (placeholders when no light casts).
struct ShadowDescriptors {
    VkDescriptorImageInfo atlas;         // raw depths (blocker search, thickness)
    VkDescriptorImageInfo atlasCompare;  // the same through the comparison sampler (filtering)
    VkDescriptorBufferInfo views;
    VkDescriptorBufferInfo lights;
};

}  // namespace candela::render
