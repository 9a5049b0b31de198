#include "candela/render/pipeline.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string_view>
#include <utility>

#include "candela/render/gpu_context.h"
#include "vk/vk_check.h"

namespace candela::render {

namespace {

VkShaderModule createShaderModule(VkDevice device, std::span<const uint32_t> spirv) {
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = spirv.size_bytes();
    info.pCode = spirv.data();
    VkShaderModule module;
    CANDELA_VK_CHECK(vkCreateShaderModule(device, &info, nullptr, &module));
    return module;
}

VkWriteDescriptorSet descriptorWrite(uint32_t binding, VkDescriptorType type) {
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstBinding = binding;
    write.descriptorCount = 1;
    write.descriptorType = type;
    return write;
}

uint64_t nanosecondsSince(std::chrono::steady_clock::time_point start) {
    return uint64_t(std::chrono::duration_cast<std::chrono::nanoseconds>(
                        std::chrono::steady_clock::now() - start)
                        .count());
}

// CANDELA_PIPELINE_LOG=1: a line on stderr per pipeline built, with its SPIR-V size and the
// driver's time, to find what a slow run compiles (--stats gives only the totals). On lavapipe
// the time follows the shader's size after inlining: one call site per big function matters.
void logPipelineCreation(const char* kind, size_t spirvWords, uint64_t createNs) {
    static const bool enabled = [] {
        const char* value = std::getenv("CANDELA_PIPELINE_LOG");
        return value && *value && std::string_view(value) != "0";
    }();
    if (!enabled) return;
    std::fprintf(stderr, "candela: %s pipeline, %zu SPIR-V words, %.1f ms\n", kind, spirvWords,
                 double(createNs) * 1e-6);
}

}  // namespace

void SpecializationConstants::set(uint32_t constantId, uint32_t value) {
    for (size_t i = 0; i < entries_.size(); ++i) {
        if (entries_[i].constantID == constantId) {
            values_[i] = value;
            return;
        }
    }
    entries_.push_back(
        {constantId, static_cast<uint32_t>(values_.size() * sizeof(uint32_t)), sizeof(uint32_t)});
    values_.push_back(value);
}

const VkSpecializationInfo* SpecializationConstants::info() {
    if (entries_.empty()) return nullptr;
    info_.mapEntryCount = static_cast<uint32_t>(entries_.size());
    info_.pMapEntries = entries_.data();
    info_.dataSize = values_.size() * sizeof(uint32_t);
    info_.pData = values_.data();
    return &info_;
}

void Pipeline::createLayout(std::span<const DescriptorBinding> bindings,
                            uint32_t pushConstantBytes) {
    VkDevice device = context_->device();
    VkPushConstantRange range{pushStages_, 0, pushConstantBytes};
    VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layoutInfo.pushConstantRangeCount = pushConstantBytes > 0 ? 1 : 0;
    layoutInfo.pPushConstantRanges = &range;
    if (bindings.empty()) {
        CANDELA_VK_CHECK(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &layout_));
        return;
    }
    std::vector<VkDescriptorSetLayoutBinding> layoutBindings;
    for (const DescriptorBinding& b : bindings) {
        layoutBindings.push_back({b.binding, b.type, 1, b.stages, nullptr});
    }
    VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    setInfo.flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR;
    setInfo.bindingCount = static_cast<uint32_t>(layoutBindings.size());
    setInfo.pBindings = layoutBindings.data();
    CANDELA_VK_CHECK(vkCreateDescriptorSetLayout(device, &setInfo, nullptr, &setLayout_));
    layoutInfo.setLayoutCount = 1;
    layoutInfo.pSetLayouts = &setLayout_;
    CANDELA_VK_CHECK(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &layout_));
}

Pipeline Pipeline::compute(GpuContext& context, std::span<const uint32_t> spirv,
                           std::span<const DescriptorBinding> bindings, uint32_t pushConstantBytes,
                           SpecializationConstants* specialization) {
    Pipeline p;
    p.context_ = &context;
    p.bindPoint_ = VK_PIPELINE_BIND_POINT_COMPUTE;
    p.pushStages_ = VK_SHADER_STAGE_COMPUTE_BIT;
    p.createLayout(bindings, pushConstantBytes);

    VkShaderModule module = createShaderModule(context.device(), spirv);
    VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    info.stage.module = module;
    info.stage.pName = "main";
    info.stage.pSpecializationInfo = specialization ? specialization->info() : nullptr;
    info.layout = p.layout_;
    const auto start = std::chrono::steady_clock::now();
    VkResult result =
        vkCreateComputePipelines(context.device(), VK_NULL_HANDLE, 1, &info, nullptr, &p.pipeline_);
    const uint64_t createNs = nanosecondsSince(start);
    context.notePipelineCreated(createNs);
    logPipelineCreation("compute", spirv.size(), createNs);
    vkDestroyShaderModule(context.device(), module, nullptr);
    if (result != VK_SUCCESS) throwVkError("vkCreateComputePipelines", result);
    return p;
}

Pipeline Pipeline::graphics(GpuContext& context, const GraphicsPipelineDesc& desc,
                            std::span<const DescriptorBinding> bindings,
                            uint32_t pushConstantBytes) {
    Pipeline p;
    p.context_ = &context;
    p.bindPoint_ = VK_PIPELINE_BIND_POINT_GRAPHICS;
    p.pushStages_ = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    p.createLayout(bindings, pushConstantBytes);

    VkDevice device = context.device();
    VkShaderModule vertex = createShaderModule(device, desc.vertexSpirv);
    VkShaderModule fragment = createShaderModule(device, desc.fragmentSpirv);
    const bool hasGeometry = !desc.geometrySpirv.empty();
    VkShaderModule geometry =
        hasGeometry ? createShaderModule(device, desc.geometrySpirv) : VK_NULL_HANDLE;
    VkPipelineShaderStageCreateInfo stages[3] = {
        {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
        {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
        {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
    stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
    stages[0].module = vertex;
    stages[0].pName = "main";
    stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
    stages[1].module = fragment;
    stages[1].pName = "main";
    stages[1].pSpecializationInfo = desc.specialization ? desc.specialization->info() : nullptr;
    stages[2].stage = VK_SHADER_STAGE_GEOMETRY_BIT;
    stages[2].module = geometry;
    stages[2].pName = "main";

    VkPipelineVertexInputStateCreateInfo vertexInput{
        VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    vertexInput.vertexBindingDescriptionCount = static_cast<uint32_t>(desc.vertexBindings.size());
    vertexInput.pVertexBindingDescriptions = desc.vertexBindings.data();
    vertexInput.vertexAttributeDescriptionCount =
        static_cast<uint32_t>(desc.vertexAttributes.size());
    vertexInput.pVertexAttributeDescriptions = desc.vertexAttributes.data();

    VkPipelineInputAssemblyStateCreateInfo inputAssembly{
        VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    inputAssembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;

    VkPipelineViewportStateCreateInfo viewport{
        VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    viewport.viewportCount = 1;
    viewport.scissorCount = 1;

    VkPipelineRasterizationStateCreateInfo raster{
        VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = desc.cullMode;
    raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    raster.lineWidth = 1.0f;

    VkPipelineMultisampleStateCreateInfo multisample{
        VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    multisample.rasterizationSamples = desc.samples;

    VkPipelineDepthStencilStateCreateInfo depth{
        VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    bool hasDepth = desc.depthFormat != VK_FORMAT_UNDEFINED;
    depth.depthTestEnable = hasDepth;
    depth.depthWriteEnable = hasDepth && desc.depthWrite;
    depth.depthCompareOp = desc.depthCompare;

    std::vector<VkPipelineColorBlendAttachmentState> blends(desc.colorFormats.size());
    for (auto& blend : blends) {
        blend.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                               VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
        if (desc.alphaBlend) {
            blend.blendEnable = VK_TRUE;
            blend.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
            blend.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
            blend.colorBlendOp = VK_BLEND_OP_ADD;
            blend.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
            blend.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
            blend.alphaBlendOp = VK_BLEND_OP_ADD;
        } else if (desc.additiveBlend) {
            blend.blendEnable = VK_TRUE;
            blend.srcColorBlendFactor = VK_BLEND_FACTOR_ONE;
            blend.dstColorBlendFactor = VK_BLEND_FACTOR_ONE;
            blend.colorBlendOp = VK_BLEND_OP_ADD;
            blend.srcAlphaBlendFactor = VK_BLEND_FACTOR_ZERO;
            blend.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
            blend.alphaBlendOp = VK_BLEND_OP_ADD;
        }
    }
    VkPipelineColorBlendStateCreateInfo colorBlend{
        VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    colorBlend.attachmentCount = static_cast<uint32_t>(blends.size());
    colorBlend.pAttachments = blends.data();

    std::vector<VkDynamicState> dynamicStates = {VK_DYNAMIC_STATE_VIEWPORT,
                                                 VK_DYNAMIC_STATE_SCISSOR};
    if (desc.dynamicCullMode) dynamicStates.push_back(VK_DYNAMIC_STATE_CULL_MODE);
    if (desc.dynamicDepthTest) dynamicStates.push_back(VK_DYNAMIC_STATE_DEPTH_TEST_ENABLE);
    VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dynamic.dynamicStateCount = static_cast<uint32_t>(dynamicStates.size());
    dynamic.pDynamicStates = dynamicStates.data();

    VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    rendering.colorAttachmentCount = static_cast<uint32_t>(desc.colorFormats.size());
    rendering.pColorAttachmentFormats = desc.colorFormats.data();
    rendering.depthAttachmentFormat = desc.depthFormat;

    VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    info.pNext = &rendering;
    info.stageCount = hasGeometry ? 3 : 2;
    info.pStages = stages;
    info.pVertexInputState = &vertexInput;
    info.pInputAssemblyState = &inputAssembly;
    info.pViewportState = &viewport;
    info.pRasterizationState = &raster;
    info.pMultisampleState = &multisample;
    info.pDepthStencilState = &depth;
    info.pColorBlendState = &colorBlend;
    info.pDynamicState = &dynamic;
    info.layout = p.layout_;
    const auto start = std::chrono::steady_clock::now();
    VkResult result =
        vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &p.pipeline_);
    const uint64_t createNs = nanosecondsSince(start);
    context.notePipelineCreated(createNs);
    logPipelineCreation(
        "graphics", desc.vertexSpirv.size() + desc.fragmentSpirv.size() + desc.geometrySpirv.size(),
        createNs);
    vkDestroyShaderModule(device, vertex, nullptr);
    vkDestroyShaderModule(device, fragment, nullptr);
    if (hasGeometry) vkDestroyShaderModule(device, geometry, nullptr);
    if (result != VK_SUCCESS) throwVkError("vkCreateGraphicsPipelines", result);
    return p;
}

Pipeline::~Pipeline() {
    release();
}

Pipeline::Pipeline(Pipeline&& other) noexcept {
    *this = std::move(other);
}

Pipeline& Pipeline::operator=(Pipeline&& other) noexcept {
    if (this != &other) {
        release();
        context_ = std::exchange(other.context_, nullptr);
        setLayout_ = std::exchange(other.setLayout_, VK_NULL_HANDLE);
        layout_ = std::exchange(other.layout_, VK_NULL_HANDLE);
        pipeline_ = std::exchange(other.pipeline_, VK_NULL_HANDLE);
        bindPoint_ = other.bindPoint_;
        pushStages_ = other.pushStages_;
    }
    return *this;
}

void Pipeline::release() {
    if (!context_) return;
    VkDevice device = context_->device();
    if (pipeline_) vkDestroyPipeline(device, pipeline_, nullptr);
    if (layout_) vkDestroyPipelineLayout(device, layout_, nullptr);
    if (setLayout_) vkDestroyDescriptorSetLayout(device, setLayout_, nullptr);
    pipeline_ = VK_NULL_HANDLE;
    layout_ = VK_NULL_HANDLE;
    setLayout_ = VK_NULL_HANDLE;
}

void Pipeline::pushDescriptors(VkCommandBuffer cmd,
                               std::span<const VkWriteDescriptorSet> writes) const {
    context_->cmdPushDescriptorSet(cmd, bindPoint_, layout_, 0,
                                   static_cast<uint32_t>(writes.size()), writes.data());
}

void Pipeline::pushConstants(VkCommandBuffer cmd, const void* data, uint32_t bytes) const {
    vkCmdPushConstants(cmd, layout_, pushStages_, 0, bytes, data);
}

VkWriteDescriptorSet storageImageWrite(uint32_t binding, const VkDescriptorImageInfo* info) {
    VkWriteDescriptorSet w = descriptorWrite(binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE);
    w.pImageInfo = info;
    return w;
}

VkWriteDescriptorSet sampledImageWrite(uint32_t binding, const VkDescriptorImageInfo* info) {
    VkWriteDescriptorSet w = descriptorWrite(binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
    w.pImageInfo = info;
    return w;
}

VkWriteDescriptorSet storageBufferWrite(uint32_t binding, const VkDescriptorBufferInfo* info) {
    VkWriteDescriptorSet w = descriptorWrite(binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    w.pBufferInfo = info;
    return w;
}

VkWriteDescriptorSet uniformBufferWrite(uint32_t binding, const VkDescriptorBufferInfo* info) {
    VkWriteDescriptorSet w = descriptorWrite(binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER);
    w.pBufferInfo = info;
    return w;
}

}  // namespace candela::render
