#pragma once
// Draws ImDrawData onto an existing RGBA8 image with one graphics pipeline (dynamic
// rendering, push descriptors): the font atlas as the only texture, vertex and index
// buffers rewritten each frame. Why our own and not imgui_impl_vulkan: 1.86's backend needs a
// VkRenderPass and descriptor pools, while every Candela pass uses dynamic rendering and push
// descriptors; this is about 200 lines.
//
// In the engine's frame it is a frame-graph pass (a runtime FrameLayer declaring the LDR target
// as a colour attachment) that calls recordInPass; record() is for an image outside a graph.
#include <imgui.h>
#include <vulkan/vulkan.h>

#include "candela/render/gpu_buffer.h"
#include "candela/render/gpu_image.h"
#include "candela/render/pipeline.h"

namespace candela::render {
class GpuContext;
}

namespace candela::ui {

class ImGuiRenderer {
public:
    // Uploads the current ImGui context's font atlas; create it after the ImGuiLayer.
    // `targetFormat` is the format of the images record() draws onto.
    ImGuiRenderer(render::GpuContext& context, VkFormat targetFormat = VK_FORMAT_R8G8B8A8_UNORM);
    ~ImGuiRenderer();
    ImGuiRenderer(const ImGuiRenderer&) = delete;
    ImGuiRenderer& operator=(const ImGuiRenderer&) = delete;

    // Records the draws onto `target` (COLOR_ATTACHMENT usage), which is in `layout` before
    // and after; earlier writes to it are made visible first. The vertex and index buffers
    // are rewritten here, so the previous submission using them must have completed
    // (FrameSubmitter::begin waits for it). Draws nothing for empty draw data.
    void record(VkCommandBuffer cmd, const ImDrawData& data, const render::GpuImage& target,
                VkImageLayout layout);
    // The same inside a frame-graph pass: `target` is already in COLOR_ATTACHMENT_OPTIMAL and
    // the graph placed the barriers around the pass, so none is recorded here.
    void recordInPass(VkCommandBuffer cmd, const ImDrawData& data, const render::GpuImage& target);

private:
    void uploadFontAtlas();

    render::GpuContext& context_;
    render::Pipeline pipeline_;
    render::GpuImage fontAtlas_;
    VkSampler sampler_ = VK_NULL_HANDLE;
    render::GpuBuffer vertices_;
    render::GpuBuffer indices_;
};

}  // namespace candela::ui
