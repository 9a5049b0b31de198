#include "passes/triangle/triangle_pass.h"

#include "candela/render/gpu_image.h"
#include "shaders/triangle.frag.spv.h"
#include "shaders/triangle.vert.spv.h"
#include "vk/rendering_attachments.h"
#include "vk/viewport.h"

namespace candela::render {

TrianglePass::TrianglePass(GpuContext& context) {
    GraphicsPipelineDesc desc;
    desc.vertexSpirv = triangle_vert_spv;
    desc.fragmentSpirv = triangle_frag_spv;
    desc.colorFormats = {VK_FORMAT_R32G32B32A32_SFLOAT};
    pipeline_ = Pipeline::graphics(context, desc, {}, sizeof(float) * 4);
}

void TrianglePass::record(VkCommandBuffer cmd, const ImageRef& target,
                          const std::array<float, 4>& clear,
                          const std::array<float, 4>& radiance) const {
    const uint32_t width = target.desc().width;
    const uint32_t height = target.desc().height;
    VkClearValue clearValue{};
    clearValue.color = {{clear[0], clear[1], clear[2], clear[3]}};
    const VkRenderingAttachmentInfo color =
        renderingAttachment(target.view(), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                            VK_ATTACHMENT_LOAD_OP_CLEAR, VK_ATTACHMENT_STORE_OP_STORE, clearValue);
    const VkRenderingInfo rendering = renderingInfo(width, height, std::span(&color, 1));

    vkCmdBeginRendering(cmd, &rendering);
    setViewportAndScissor(cmd, width, height);
    pipeline_.bind(cmd);
    pipeline_.pushConstants(cmd, radiance.data(), sizeof(float) * 4);
    vkCmdDraw(cmd, 3, 1, 0, 0);
    vkCmdEndRendering(cmd);
}

}  // namespace candela::render
