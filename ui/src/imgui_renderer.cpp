#include "candela/ui/imgui_renderer.h"

#include <algorithm>
#include <cstddef>
#include <cstring>

#include "candela/render/gpu_context.h"
#include "overlay_pass_support.h"
#include "shaders/imgui.frag.spv.h"
#include "shaders/imgui.vert.spv.h"

namespace candela::ui {

namespace {

static_assert(sizeof(ImDrawIdx) == 2, "the draw pass binds 16-bit indices");

constexpr render::DescriptorBinding kBindings[] = {
    {0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT}};

struct PushConstants {
    float scale[2];
    float translate[2];
};

}  // namespace

ImGuiRenderer::ImGuiRenderer(render::GpuContext& context, VkFormat targetFormat)
    : context_(context) {
    render::GraphicsPipelineDesc desc;
    desc.vertexSpirv = imgui_vert_spv;
    desc.fragmentSpirv = imgui_frag_spv;
    desc.vertexBindings = {{0, sizeof(ImDrawVert), VK_VERTEX_INPUT_RATE_VERTEX}};
    desc.vertexAttributes = {{0, 0, VK_FORMAT_R32G32_SFLOAT, uint32_t(offsetof(ImDrawVert, pos))},
                             {1, 0, VK_FORMAT_R32G32_SFLOAT, uint32_t(offsetof(ImDrawVert, uv))},
                             {2, 0, VK_FORMAT_R8G8B8A8_UNORM, uint32_t(offsetof(ImDrawVert, col))}};
    desc.colorFormats = {targetFormat};
    desc.alphaBlend = true;
    pipeline_ = render::Pipeline::graphics(context_, desc, kBindings, sizeof(PushConstants));

    sampler_ = makeClampedLinearSampler(context_);
    uploadFontAtlas();
}

ImGuiRenderer::~ImGuiRenderer() {
    if (sampler_) vkDestroySampler(context_.device(), sampler_, nullptr);
}

void ImGuiRenderer::uploadFontAtlas() {
    ImGuiIO& io = ImGui::GetIO();
    unsigned char* pixels = nullptr;
    int width = 0;
    int height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
    fontAtlas_ = render::GpuImage(
        context_, {VK_FORMAT_R8G8B8A8_UNORM, uint32_t(width), uint32_t(height), 1, false,
                   VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT});
    uploadTexture(context_, fontAtlas_, pixels, VkDeviceSize(width) * VkDeviceSize(height) * 4,
                  true);
    io.Fonts->SetTexID(reinterpret_cast<ImTextureID>(&fontAtlas_));
}

void ImGuiRenderer::record(VkCommandBuffer cmd, const ImDrawData& data,
                           const render::GpuImage& target, VkImageLayout layout) {
    if (data.TotalVtxCount <= 0 || data.CmdListsCount <= 0) return;
    // Whatever wrote or read the target before (tonemap, copies) finishes first.
    render::transitionImage(
        cmd, target, layout, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
        VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
        VK_ACCESS_2_MEMORY_WRITE_BIT | VK_ACCESS_2_MEMORY_READ_BIT,
        VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
        VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    recordInPass(cmd, data, target);
    render::transitionImage(cmd, target, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, layout,
                            VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                            VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                            VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                            VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT);
}

void ImGuiRenderer::recordInPass(VkCommandBuffer cmd, const ImDrawData& data,
                                 const render::GpuImage& target) {
    if (data.TotalVtxCount <= 0 || data.CmdListsCount <= 0) return;
    const uint32_t width = target.desc().width;
    const uint32_t height = target.desc().height;

    growHostBuffer(context_, vertices_, VkDeviceSize(data.TotalVtxCount) * sizeof(ImDrawVert),
                   VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, 64 * 1024);
    growHostBuffer(context_, indices_, VkDeviceSize(data.TotalIdxCount) * sizeof(ImDrawIdx),
                   VK_BUFFER_USAGE_INDEX_BUFFER_BIT, 64 * 1024);
    auto* vertexOut = static_cast<ImDrawVert*>(vertices_.mapped());
    auto* indexOut = static_cast<ImDrawIdx*>(indices_.mapped());
    for (int n = 0; n < data.CmdListsCount; ++n) {
        const ImDrawList* list = data.CmdLists[n];
        std::memcpy(vertexOut, list->VtxBuffer.Data,
                    size_t(list->VtxBuffer.Size) * sizeof(ImDrawVert));
        std::memcpy(indexOut, list->IdxBuffer.Data,
                    size_t(list->IdxBuffer.Size) * sizeof(ImDrawIdx));
        vertexOut += list->VtxBuffer.Size;
        indexOut += list->IdxBuffer.Size;
    }

    beginOverlayRendering(cmd, target);

    // ImGui positions are in display units; the target may differ from the display size
    // (a window blitted to a larger swapchain), so stretch the display rectangle over it.
    const ImVec2 displayPos = data.DisplayPos;
    const ImVec2 displaySize = data.DisplaySize;
    const float toTargetX = displaySize.x > 0.0f ? float(width) / displaySize.x : 1.0f;
    const float toTargetY = displaySize.y > 0.0f ? float(height) / displaySize.y : 1.0f;
    auto bindState = [&] {
        pipeline_.bind(cmd);
        VkDescriptorImageInfo font{sampler_, fontAtlas_.view(),
                                   VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
        VkWriteDescriptorSet write = render::sampledImageWrite(0, &font);
        pipeline_.pushDescriptors(cmd, {&write, 1});
        PushConstants pc{};
        pc.scale[0] = 2.0f / displaySize.x;
        pc.scale[1] = 2.0f / displaySize.y;
        pc.translate[0] = -1.0f - displayPos.x * pc.scale[0];
        pc.translate[1] = -1.0f - displayPos.y * pc.scale[1];
        pipeline_.pushConstants(cmd, &pc, sizeof(pc));
        VkDeviceSize offset = 0;
        VkBuffer vertexBuffer = vertices_.handle();
        vkCmdBindVertexBuffers(cmd, 0, 1, &vertexBuffer, &offset);
        vkCmdBindIndexBuffer(cmd, indices_.handle(), 0, VK_INDEX_TYPE_UINT16);
    };
    bindState();

    uint32_t vertexBase = 0;
    uint32_t indexBase = 0;
    for (int n = 0; n < data.CmdListsCount; ++n) {
        const ImDrawList* list = data.CmdLists[n];
        for (const ImDrawCmd& command : list->CmdBuffer) {
            if (command.UserCallback) {
                if (command.UserCallback == ImDrawCallback_ResetRenderState) {
                    bindState();
                } else {
                    command.UserCallback(list, &command);
                }
                continue;
            }
            // Clip rectangle in target pixels, clamped to the target (Vulkan rejects
            // negative offsets).
            float x0 = std::max((command.ClipRect.x - displayPos.x) * toTargetX, 0.0f);
            float y0 = std::max((command.ClipRect.y - displayPos.y) * toTargetY, 0.0f);
            float x1 = std::min((command.ClipRect.z - displayPos.x) * toTargetX, float(width));
            float y1 = std::min((command.ClipRect.w - displayPos.y) * toTargetY, float(height));
            if (x1 <= x0 || y1 <= y0) continue;
            VkRect2D scissor{
                {int32_t(x0), int32_t(y0)},
                {uint32_t(x1 - float(int32_t(x0))), uint32_t(y1 - float(int32_t(y0)))}};
            vkCmdSetScissor(cmd, 0, 1, &scissor);
            vkCmdDrawIndexed(cmd, command.ElemCount, 1, indexBase + command.IdxOffset,
                             int32_t(vertexBase + command.VtxOffset), 0);
        }
        vertexBase += uint32_t(list->VtxBuffer.Size);
        indexBase += uint32_t(list->IdxBuffer.Size);
    }
    vkCmdEndRendering(cmd);
}

}  // namespace candela::ui
