#pragma once
// Exposure + filmic tonemap + sRGB encode, as a compute pass over the HDR target.
#include "candela/render/pipeline.h"
#include "frame_graph/graph_resources.h"

namespace candela::render {

class GpuContext;

class TonemapPass {
public:
    explicit TonemapPass(GpuContext& context);
    // hdr must be in GENERAL layout and readable; ldr in GENERAL layout.
    void record(VkCommandBuffer cmd, const ImageRef& hdr, const ImageRef& ldr,
                float exposure) const;

private:
    Pipeline pipeline_;
};

}  // namespace candela::render
