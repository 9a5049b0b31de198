#include "compute_harness.h"

#include <stdexcept>

namespace candela::stability {

namespace {

render::GpuContextOptions requiredValidation() {
    render::GpuContextOptions options;
    options.validation = render::ValidationMode::Required;
    return options;
}

}  // namespace

ComputeHarness::ComputeHarness() : context_(requiredValidation()) {}

render::GpuBuffer ComputeHarness::buffer(size_t bytes) {
    render::GpuBuffer b(context_, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                        render::MemoryLocation::HostVisible);
    std::memset(b.mapped(), 0, bytes);
    return b;
}

render::Pipeline ComputeHarness::pipeline(std::span<const uint32_t> spirv, uint32_t bufferCount,
                                          uint32_t pushConstantBytes) {
    std::vector<render::DescriptorBinding> bindings;
    for (uint32_t i = 0; i < bufferCount; ++i) {
        bindings.push_back({i, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT});
    }
    return render::Pipeline::compute(context_, spirv, bindings, pushConstantBytes);
}

void ComputeHarness::dispatch(const render::Pipeline& pipeline,
                              std::initializer_list<const render::GpuBuffer*> buffers,
                              const void* pushConstants, uint32_t pushConstantBytes,
                              uint32_t groupCountX) {
    if (groupCountX > context_.properties().limits.maxComputeWorkGroupCount[0]) {
        throw std::runtime_error("stability dispatch exceeds maxComputeWorkGroupCount[0]");
    }
    std::vector<VkDescriptorBufferInfo> infos;
    infos.reserve(buffers.size());
    for (const render::GpuBuffer* b : buffers)
        infos.push_back({b->handle(), 0, VK_WHOLE_SIZE});
    std::vector<VkWriteDescriptorSet> writes;
    for (uint32_t i = 0; i < infos.size(); ++i) {
        writes.push_back(render::storageBufferWrite(i, &infos[i]));
    }
    context_.submitAndWait([&](VkCommandBuffer cmd) {
        pipeline.bind(cmd);
        pipeline.pushDescriptors(cmd, writes);
        if (pushConstantBytes > 0) pipeline.pushConstants(cmd, pushConstants, pushConstantBytes);
        vkCmdDispatch(cmd, groupCountX, 1, 1);
        VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        toHost.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
        toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                             0, 1, &toHost, 0, nullptr, 0, nullptr);
    });
}

}  // namespace candela::stability
