#pragma once
// The luminance histogram pass (luminance_histogram.comp) for automatic exposure.
#include "candela/render/pipeline.h"
#include "frame_graph/graph_resources.h"

namespace candela::render {

class GpuContext;

class ExposureHistogramPass {
public:
    explicit ExposureHistogramPass(GpuContext& context);
    // hdr: StorageRead; histogram: TransferDst then StorageReadWrite (cleared here first).
    void record(VkCommandBuffer cmd, const ImageRef& hdr, const BufferRef& histogram) const;

private:
    Pipeline pipeline_;
};

}  // namespace candela::render
