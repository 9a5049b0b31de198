#pragma once
// A pipeline with its layout and one push-descriptor set layout: what a pass binds.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <vector>

namespace candela::render {

class GpuContext;

struct DescriptorBinding {
    uint32_t binding;
    VkDescriptorType type;
    VkShaderStageFlags stages;
};

// Specialization constants: how a scene's feature set selects a shader variant.
class SpecializationConstants {
public:
    void set(uint32_t constantId, uint32_t value);
    const VkSpecializationInfo* info();  // null when empty

private:
    std::vector<VkSpecializationMapEntry> entries_;
    std::vector<uint32_t> values_;
    VkSpecializationInfo info_{};
};

struct GraphicsPipelineDesc {
    std::span<const uint32_t> vertexSpirv;
    std::span<const uint32_t> fragmentSpirv;
    // Optional (empty: none): needs GpuContext::geometryShaders().
    std::span<const uint32_t> geometrySpirv;
    std::vector<VkVertexInputBindingDescription> vertexBindings;
    std::vector<VkVertexInputAttributeDescription> vertexAttributes;
    std::vector<VkFormat> colorFormats;
    VkFormat depthFormat = VK_FORMAT_UNDEFINED;
    VkCompareOp depthCompare = VK_COMPARE_OP_GREATER_OR_EQUAL;  // reverse-Z
    bool depthWrite = true;
    VkCullModeFlags cullMode = VK_CULL_MODE_NONE;
    bool dynamicCullMode = false;   // set per draw with vkCmdSetCullMode instead
    bool dynamicDepthTest = false;  // set per draw with vkCmdSetDepthTestEnable instead
    // colour = src * srcAlpha + dst * (1 - srcAlpha): UI overlays, glTF BLEND (straight alpha)
    bool alphaBlend = false;
    // colour = src + dst, alpha = dst (sums into a target whose alpha holds data of its own:
    // the per-light volumes' view depth)
    bool additiveBlend = false;
    // Samples per pixel of every attachment (the forward pass's MSAA targets).
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    SpecializationConstants* specialization = nullptr;  // applied to the fragment stage
};

class Pipeline {
public:
    Pipeline() = default;
    static Pipeline compute(GpuContext& context, std::span<const uint32_t> spirv,
                            std::span<const DescriptorBinding> bindings, uint32_t pushConstantBytes,
                            SpecializationConstants* specialization = nullptr);
    static Pipeline graphics(GpuContext& context, const GraphicsPipelineDesc& desc,
                             std::span<const DescriptorBinding> bindings,
                             uint32_t pushConstantBytes);
    ~Pipeline();
    Pipeline(Pipeline&& other) noexcept;
    Pipeline& operator=(Pipeline&& other) noexcept;
    Pipeline(const Pipeline&) = delete;
    Pipeline& operator=(const Pipeline&) = delete;

    VkPipeline handle() const { return pipeline_; }
    VkPipelineLayout layout() const { return layout_; }
    VkPipelineBindPoint bindPoint() const { return bindPoint_; }

    void bind(VkCommandBuffer cmd) const { vkCmdBindPipeline(cmd, bindPoint_, pipeline_); }
    void pushDescriptors(VkCommandBuffer cmd, std::span<const VkWriteDescriptorSet> writes) const;
    void pushConstants(VkCommandBuffer cmd, const void* data, uint32_t bytes) const;

private:
    void createLayout(std::span<const DescriptorBinding> bindings, uint32_t pushConstantBytes);
    void release();

    const GpuContext* context_ = nullptr;
    VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
    VkPipelineBindPoint bindPoint_ = VK_PIPELINE_BIND_POINT_COMPUTE;
    VkShaderStageFlags pushStages_ = 0;
};

// Descriptor write helpers for push descriptors (dstSet is ignored by vkCmdPushDescriptorSetKHR).
VkWriteDescriptorSet storageImageWrite(uint32_t binding, const VkDescriptorImageInfo* info);
VkWriteDescriptorSet sampledImageWrite(uint32_t binding, const VkDescriptorImageInfo* info);
VkWriteDescriptorSet storageBufferWrite(uint32_t binding, const VkDescriptorBufferInfo* info);
VkWriteDescriptorSet uniformBufferWrite(uint32_t binding, const VkDescriptorBufferInfo* info);

}  // namespace candela::render
