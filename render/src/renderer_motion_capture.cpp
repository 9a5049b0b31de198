// The motion-vector capture (RendererOptions::captureMotionVectors): the frame's final motion
// vectors copied into a host-visible buffer, and reading them back.

#include <cstdint>
#include <glm/gtc/packing.hpp>
#include <vector>

#include "candela/render/renderer.h"
#include "features/declared_frame.h"
#include "frame_graph/frame_graph.h"
#include "frame_graph/frame_graph_executor.h"

namespace candela::render {

void Renderer::declareMotionCapture(ResourceHandle motion) {
    FrameGraph& g = *graph_;
    const VkDeviceSize bytes =
        VkDeviceSize(targets_.width) * targets_.height * 2 * sizeof(uint16_t);
    if (targets_.motionReadback.size() != bytes) {
        targets_.motionReadback = GpuBuffer(context_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                            MemoryLocation::HostVisible);
    }
    const ResourceHandle readback =
        g.importBuffer("motion.readback", &targets_.motionReadback, true);
    auto p = g.addPass("motion_capture", PassKind::Device, [this, motion](PassContext& ctx) {
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {targets_.width, targets_.height, 1};
        vkCmdCopyImageToBuffer(ctx.cmd(), ctx.image(motion).handle(),
                               VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                               targets_.motionReadback.handle(), 1, &region);
    });
    p.read(motion, Use::TransferSrc);
    p.write(readback, Use::TransferDst);
    p.sideEffect();
}

std::vector<glm::vec2> Renderer::motionVectors() const {
    std::vector<glm::vec2> motion;
    if (targets_.motionReadback.size() == 0 || frame_->recorded == RecordedFrame::None)
        return motion;
    const auto* halves = static_cast<const uint16_t*>(targets_.motionReadback.mapped());
    motion.resize(size_t(targets_.width) * targets_.height);
    for (size_t i = 0; i < motion.size(); ++i)
        motion[i] = {glm::unpackHalf1x16(halves[i * 2]), glm::unpackHalf1x16(halves[i * 2 + 1])};
    return motion;
}

}  // namespace candela::render
