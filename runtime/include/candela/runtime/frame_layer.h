#pragma once
// Drawing of one's own on top of the frame (an ImGui overlay, debug lines): a FrameLayer adds
// one pass to the frame graph. It declares which of the frame's images it reads and writes and
// how (render/frame_target_use.h); the graph orders the pass after tonemapping, places every
// barrier and layout transition, and calls record() with an opaque LayerPassContext. Captures
// and the window show the result. Vulkan-free: a layer that records Vulkan commands includes
// candela/runtime/layer_pass_context.h in its own source file.
//
//   class Crosshair : public FrameLayer {
//       std::vector<render::TargetAccess> uses() const override {
//           return {{render::FrameTarget::Ldr, render::TargetUse::ColorAttachment}};
//       }
//       void record(LayerPassContext& pass) override { ... pass.commandBuffer() ... }
//   };
//   app.addLayer(std::make_shared<Crosshair>());
#include <string>
#include <vector>

#include "candela/render/frame_target_use.h"

namespace candela::render {
class GpuContext;
}  // namespace candela::render

namespace candela::runtime {

class LayerPassContext;
class Window;
struct FrameContext;
struct FrameStats;

class FrameLayer {
public:
    virtual ~FrameLayer() = default;
    // The pass's name in --stats "passes" and --frame-graph.
    virtual std::string name() const = 0;
    // Once the device exists; `window` is null when headless.
    virtual void start(render::GpuContext& context, Window* window) = 0;
    // What the pass reads and writes this frame; empty: no pass this frame.
    virtual std::vector<render::TargetAccess> uses() const = 0;
    // On the CPU before the frame records (build UI here); `stats` are the previous frame's.
    virtual void prepare(const FrameContext& frame, const FrameStats& stats) = 0;
    // Inside the frame graph, with each declared image in the layout its use needs.
    virtual void record(LayerPassContext& pass) = 0;
    // Before the device is destroyed.
    virtual void stop() = 0;
};

}  // namespace candela::runtime
