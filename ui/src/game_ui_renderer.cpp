#include "candela/ui/game_ui_renderer.h"

#include <cstddef>
#include <cstring>

#include "candela/render/gpu_context.h"
#include "overlay_pass_support.h"
#include "shaders/game_ui.frag.spv.h"
#include "shaders/game_ui.vert.spv.h"

namespace candela::ui {
namespace {

constexpr render::DescriptorBinding kBindings[] = {
    {0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT}};

struct PushConstants {
    float scale[2];
    float translate[2];
};

}  // namespace

GameUiRenderer::GameUiRenderer(render::GpuContext& context, VkFormat targetFormat)
    : context_(context) {
    using gameui::UiVertex;
    render::GraphicsPipelineDesc desc;
    desc.vertexSpirv = game_ui_vert_spv;
    desc.fragmentSpirv = game_ui_frag_spv;
    desc.vertexBindings = {{0, sizeof(UiVertex), VK_VERTEX_INPUT_RATE_VERTEX}};
    desc.vertexAttributes = {{0, 0, VK_FORMAT_R32G32_SFLOAT, uint32_t(offsetof(UiVertex, x))},
                             {1, 0, VK_FORMAT_R32G32_SFLOAT, uint32_t(offsetof(UiVertex, u))},
                             {2, 0, VK_FORMAT_R8G8B8A8_UNORM, uint32_t(offsetof(UiVertex, rgba))}};
    desc.colorFormats = {targetFormat};
    desc.alphaBlend = true;
    pipeline_ = render::Pipeline::graphics(context_, desc, kBindings, sizeof(PushConstants));
    // Linear for images drawn at another size; glyphs are one texel per pixel with fragment
    // centres on texel centres, where linear filtering returns the texel itself.
    sampler_ = makeClampedLinearSampler(context_);
}

GameUiRenderer::~GameUiRenderer() {
    if (sampler_) vkDestroySampler(context_.device(), sampler_, nullptr);
}

void GameUiRenderer::uploadAtlas(const gameui::GlyphAtlas& atlas) {
    const std::uint32_t size = atlas.size();
    const bool fresh = atlas_.handle() == VK_NULL_HANDLE || atlas_.desc().width != size;
    if (fresh) {
        atlas_ = render::GpuImage(context_,
                                  {VK_FORMAT_R8G8B8A8_UNORM, size, size, 1, false,
                                   VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT});
    }
    uploadTexture(context_, atlas_, atlas.pixels().data(), VkDeviceSize(size) * size * 4, fresh);
}

void GameUiRenderer::prepare(gameui::GlyphAtlas& atlas, const gameui::UiDrawList& list) {
    indexCount_ = std::uint32_t(list.indices.size());
    if (indexCount_ == 0) return;
    if (atlas.dirty() || atlas_.handle() == VK_NULL_HANDLE) {
        uploadAtlas(atlas);
        atlas.markUploaded();
    }
    growHostBuffer(context_, vertices_, list.vertices.size() * sizeof(gameui::UiVertex),
                   VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, 16 * 1024);
    growHostBuffer(context_, indices_, list.indices.size() * sizeof(std::uint32_t),
                   VK_BUFFER_USAGE_INDEX_BUFFER_BIT, 16 * 1024);
    std::memcpy(vertices_.mapped(), list.vertices.data(),
                list.vertices.size() * sizeof(gameui::UiVertex));
    std::memcpy(indices_.mapped(), list.indices.data(),
                list.indices.size() * sizeof(std::uint32_t));
}

void GameUiRenderer::recordInPass(VkCommandBuffer cmd, const render::GpuImage& target) {
    if (indexCount_ == 0) return;
    const uint32_t width = target.desc().width, height = target.desc().height;
    beginOverlayRendering(cmd, target);
    VkRect2D scissor{{0, 0}, {width, height}};
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    pipeline_.bind(cmd);
    VkDescriptorImageInfo image{sampler_, atlas_.view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkWriteDescriptorSet write = render::sampledImageWrite(0, &image);
    pipeline_.pushDescriptors(cmd, {&write, 1});
    PushConstants pc{{2.0f / float(width), 2.0f / float(height)}, {-1.0f, -1.0f}};
    pipeline_.pushConstants(cmd, &pc, sizeof(pc));
    VkDeviceSize offset = 0;
    VkBuffer vertexBuffer = vertices_.handle();
    vkCmdBindVertexBuffers(cmd, 0, 1, &vertexBuffer, &offset);
    vkCmdBindIndexBuffer(cmd, indices_.handle(), 0, VK_INDEX_TYPE_UINT32);
    vkCmdDrawIndexed(cmd, indexCount_, 1, 0, 0, 0);
    vkCmdEndRendering(cmd);
}

}  // namespace candela::ui
