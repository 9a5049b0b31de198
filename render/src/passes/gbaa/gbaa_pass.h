#pragma once
// GBAA's resolve (gbaa.comp): blends each pixel of the lit HDR radiance with its neighbour
// across the triangle edge the G-buffer pass found in it, into a transient that is copied back
// into the HDR target (like TAA's resolve) so exposure, bloom, tonemapping and the .exr
// capture see it. render/README.md "GBAA".
#include "candela/render/pipeline.h"
#include "frame_graph/graph_resources.h"
#include "vk/sampler.h"

namespace candela::render {

class GpuContext;

class GbaaPass {
public:
    explicit GbaaPass(GpuContext& context);
    // hdr: StorageRead; edges (gbuffer.edges): Sampled; resolved: StorageWrite (RGBA32F, the
    // HDR target's size).
    void recordResolve(VkCommandBuffer cmd, const ImageRef& hdr, const ImageRef& edges,
                       const ImageRef& resolved) const;

private:
    Pipeline pipeline_;
    Sampler nearest_;
};

}  // namespace candela::render
