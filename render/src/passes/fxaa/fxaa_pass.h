#pragma once
// Post-process antialiasing (fxaa.comp) from the tonemapped image into the LDR target, for
// frames without history (render/README.md "Antialiasing" says why FXAA rather than SMAA).
#include "candela/render/pipeline.h"
#include "frame_graph/graph_resources.h"
#include "vk/sampler.h"

namespace candela::render {

class GpuContext;

class FxaaPass {
public:
    explicit FxaaPass(GpuContext& context);
    // tonemapped: Sampled (RGBA8, sRGB-encoded values); ldr: StorageWrite.
    void record(VkCommandBuffer cmd, const ImageRef& tonemapped, const ImageRef& ldr) const;

private:
    Pipeline pipeline_;
    Sampler linear_;
};

}  // namespace candela::render
