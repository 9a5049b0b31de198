// The motion-vector capture (RendererOptions::captureMotionVectors): the frame's final motion
// vectors copied into a host-visible buffer, and reading them back.

#include <cstdint>
#include <glm/gtc/packing.hpp>
#include <vector>

#include "candela/render/renderer.h"
#include "frame_graph/frame_graph.h"
#include "frame_graph/frame_graph_executor.h"

namespace candela::render {

void Renderer::declareMotionCapture(ResourceHandle motion) {
    FrameGraph& g = *graph_;
    const VkDeviceSize bytes = VkDeviceSize(width_) * height_ * 2 * sizeof(uint16_t);
    if (motionReadback_.size() != bytes) {
        motionReadback_ = GpuBuffer(context_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                    MemoryLocation::HostVisible);
    }
    const ResourceHandle readback = g.importBuffer("motion.readback", &motionReadback_, true);
    auto p = g.addPass("motion_capture", PassKind::Device, [this, motion](PassContext& ctx) {
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {width_, height_, 1};
        vkCmdCopyImageToBuffer(ctx.cmd(), ctx.image(motion).handle(),
                               VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, motionReadback_.handle(), 1,
                               &region);
    });
    p.read(motion, Use::TransferSrc);
    p.write(readback, Use::TransferDst);
    p.sideEffect();
}

std::vector<glm::vec2> Renderer::motionVectors() const {
    std::vector<glm::vec2> motion;
    if (motionReadback_.size() == 0 || recorded_ == RecordedFrame::None) return motion;
    const auto* halves = static_cast<const uint16_t*>(motionReadback_.mapped());
    motion.resize(size_t(width_) * height_);
    for (size_t i = 0; i < motion.size(); ++i)
        motion[i] = {glm::unpackHalf1x16(halves[i * 2]), glm::unpackHalf1x16(halves[i * 2 + 1])};
    return motion;
}

}  // namespace candela::render
