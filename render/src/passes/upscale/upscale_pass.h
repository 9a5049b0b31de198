#pragma once
// Radiance rendered below the output's size (RendererOptions::renderScale) filtered up to it
// (upscale.comp), between the HDR post effects and tonemapping.
#include "candela/render/pipeline.h"
#include "frame_graph/graph_resources.h"
#include "vk/sampler.h"

namespace candela::render {

class GpuContext;

class UpscalePass {
public:
    explicit UpscalePass(GpuContext& context);
    // source: Sampled (RGBA32F at the render size); target: StorageWrite (RGBA32F, output size).
    void record(VkCommandBuffer cmd, const ImageRef& source, const ImageRef& target) const;

private:
    Pipeline pipeline_;
    Sampler linear_;
};

}  // namespace candela::render
