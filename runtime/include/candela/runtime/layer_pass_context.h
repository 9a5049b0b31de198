#pragma once
// What a FrameLayer's pass records with: the frame's command buffer and its images, each in
// the layout the layer declared a use for (Renderer::targetLayout). Engine-side (Vulkan): only
// a layer's own source includes it; frame_layer.h does not.
#include <vulkan/vulkan.h>

#include <cstdint>

#include "candela/render/frame_target_use.h"

namespace candela::render {
class GpuImage;
class Renderer;
}  // namespace candela::render

namespace candela::runtime {

class LayerPassContext {
public:
    LayerPassContext(VkCommandBuffer cmd, const render::Renderer& renderer)
        : cmd_(cmd), renderer_(renderer) {}

    VkCommandBuffer commandBuffer() const { return cmd_; }
    const render::GpuImage& image(render::FrameTarget target) const;
    // Render size in pixels.
    std::uint32_t width() const;
    std::uint32_t height() const;

private:
    VkCommandBuffer cmd_;
    const render::Renderer& renderer_;
};

}  // namespace candela::runtime
