#include "passes/triangle/triangle_pass.h"

#include "candela/render/gpu_image.h"
#include "shaders/triangle.frag.spv.h"
#include "shaders/triangle.vert.spv.h"
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
    VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    color.imageView = target.view();
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    color.clearValue.color = {{clear[0], clear[1], clear[2], clear[3]}};
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, {width, height}};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachments = &color;

    vkCmdBeginRendering(cmd, &rendering);
    setViewportAndScissor(cmd, width, height);
    pipeline_.bind(cmd);
    pipeline_.pushConstants(cmd, radiance.data(), sizeof(float) * 4);
    vkCmdDraw(cmd, 3, 1, 0, 0);
    vkCmdEndRendering(cmd);
}

}  // namespace candela::render
