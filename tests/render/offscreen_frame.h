#pragma once
// Test support: render one frame offscreen with validation required, and read it back.
#include <cstdint>

#include "candela/render/frame_capture.h"
#include "candela/render/frame_inputs.h"
#include "candela/render/frame_submitter.h"
#include "candela/render/gpu_context.h"
#include "candela/render/renderer.h"
#include "candela/render/scene_resources.h"

namespace candela::render::test {

inline GpuContextOptions requiredValidation() {
    GpuContextOptions options;
    options.validation = ValidationMode::Required;
    return options;
}

// One device for the whole test binary: making one costs as much as a 128x128 frame on
// lavapipe.
inline GpuContext& sharedContext() {
    static GpuContext context(requiredValidation());
    return context;
}

inline CapturedFrame renderOffscreen(GpuContext& context, const FrameInputs& inputs, uint32_t width,
                                     uint32_t height, uint32_t frames = 1,
                                     SceneResources* resources = nullptr,
                                     const RendererOptions& options = {},
                                     RendererStats* stats = nullptr) {
    Renderer renderer(context, width, height, options);
    FrameSubmitter submitter(context);
    FrameReadback readback(context, width, height);
    for (uint32_t i = 0; i < frames; ++i) {
        VkCommandBuffer cmd = renderer.recordFrame(submitter, inputs, resources);
        if (i + 1 == frames) readback.recordCopy(cmd, renderer);
        submitter.submit();
        submitter.waitIdle();
        if (stats) *stats = renderer.collectStats();
    }
    return readback.read();
}

// One renderer kept from frame to frame (its history and caches carry over), each frame
// rendered into `resources`' scene and read back.
class FrameSequence {
public:
    FrameSequence(GpuContext& context, uint32_t width, uint32_t height,
                  const RendererOptions& options = {})
        : renderer_(context, width, height, options),
          submitter_(context),
          readback_(context, width, height) {}

    CapturedFrame render(const FrameInputs& inputs, SceneResources& resources,
                         RendererStats* stats = nullptr) {
        VkCommandBuffer cmd = renderer_.recordFrame(submitter_, inputs, &resources);
        readback_.recordCopy(cmd, renderer_);
        submitter_.submit();
        submitter_.waitIdle();
        if (stats) *stats = renderer_.collectStats();
        return readback_.read();
    }

private:
    Renderer renderer_;
    FrameSubmitter submitter_;
    FrameReadback readback_;
};

}  // namespace candela::render::test
