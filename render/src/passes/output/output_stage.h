#pragma once
// From the scene's HDR target to the image a player sees: the upscale to the output size (a
// render scale below 1), then tonemapping, FXAA (--aa fxaa) and the debug text over the LDR
// target.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "candela/render/renderer_options.h"
#include "candela/render/text_overlay.h"
#include "frame_graph/frame_graph.h"

namespace candela::render {

class DebugTextPass;
class FxaaPass;
class GpuContext;
class TonemapPass;
class UpscalePass;

class OutputStage {
public:
    OutputStage(GpuContext& context, const RendererOptions& options);
    ~OutputStage();
    // Whether the scene renders below the output size: the upscale pass exists exactly then.
    void setUpscales(bool upscales);
    bool upscales() const { return upscale_ != nullptr; }

    // `hdr` (render size) filtered into `outputHdr` (output size); returns its new version.
    ResourceHandle declareUpscale(FrameGraph& g, ResourceHandle hdr, ResourceHandle outputHdr,
                                  std::vector<std::string>& features);
    // Tonemapping (and FXAA) from `hdr` into `ldr`, then `text` over it; returns the LDR target
    // as the passes after tonemapping see it.
    ResourceHandle declareDisplay(FrameGraph& g, ResourceHandle hdr, ResourceHandle ldr,
                                  float exposure, const std::vector<TextLine>& text,
                                  uint32_t outputWidth, uint32_t outputHeight,
                                  std::vector<std::string>& features);

private:
    GpuContext& context_;
    std::unique_ptr<UpscalePass> upscale_;
    std::unique_ptr<TonemapPass> tonemap_;
    std::unique_ptr<FxaaPass> fxaa_;            // --aa fxaa only
    std::unique_ptr<DebugTextPass> debugText_;  // made on the first frame with text
};

}  // namespace candela::render
