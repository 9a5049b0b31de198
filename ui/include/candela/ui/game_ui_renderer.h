#pragma once
// Draws a gameui::UiDrawList (the game's widgets, images and text) onto the LDR target inside a
// frame-graph pass: one pipeline (dynamic rendering, push descriptors, alpha blending in
// display-encoded space, as the target holds sRGB-encoded values) sampling the atlas, an RGBA8
// image uploaded again only when new glyphs or images were placed in it.
#include <vulkan/vulkan.h>

#include "candela/gameui/glyph_atlas.h"
#include "candela/gameui/ui_draw_list.h"
#include "candela/render/gpu_buffer.h"
#include "candela/render/gpu_image.h"
#include "candela/render/pipeline.h"

namespace candela::render {
class GpuContext;
}

namespace candela::ui {

class GameUiRenderer {
public:
    explicit GameUiRenderer(render::GpuContext& context,
                            VkFormat targetFormat = VK_FORMAT_R8G8B8A8_UNORM);
    ~GameUiRenderer();
    GameUiRenderer(const GameUiRenderer&) = delete;
    GameUiRenderer& operator=(const GameUiRenderer&) = delete;

    // Before the frame records: uploads the atlas if it changed (a submission of its own, so
    // no frame's commands touch the atlas while it is written) and the draw list's vertices.
    // The previous frame's submission must have completed (FrameSubmitter::begin waits).
    void prepare(gameui::GlyphAtlas& atlas, const gameui::UiDrawList& list);
    // Inside the pass: `target` is in COLOR_ATTACHMENT_OPTIMAL and the graph placed the
    // barriers. Draws what prepare() was given; nothing for an empty list.
    void recordInPass(VkCommandBuffer cmd, const render::GpuImage& target);

private:
    void uploadAtlas(const gameui::GlyphAtlas& atlas);

    render::GpuContext& context_;
    render::Pipeline pipeline_;
    render::GpuImage atlas_;
    VkSampler sampler_ = VK_NULL_HANDLE;
    render::GpuBuffer vertices_;
    render::GpuBuffer indices_;
    std::uint32_t indexCount_ = 0;
};

}  // namespace candela::ui
