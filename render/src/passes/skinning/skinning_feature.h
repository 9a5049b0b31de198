#pragma once
// GPU skinning and morph targets as a frame feature (frames with animated draws): one compute
// pass deforms every animated draw before any geometry pass draws it. Publishes
// DeformedVertices, which shadows, the G-buffer, cluster marks and blended surfaces read.
#include <memory>

#include "features/render_feature.h"

namespace candela::render {

class GpuContext;
class SkinningPass;

// Every deformed vertex buffer at once: the graph synchronises buffers with global memory
// barriers, so one resource orders the writes and the reads.
struct DeformedVertices {
    ResourceHandle buffers;
};

class SkinningFeature final : public RenderFeature {
public:
    explicit SkinningFeature(GpuContext& context);
    ~SkinningFeature() override;
    bool active(const FeatureFrame& frame) const override;
    void declare(FeatureFrame& frame) override;
    // skinning_ms.
    void collectStats(RendererStats& stats, bool declared) const override;

private:
    GpuContext& context_;
    std::unique_ptr<SkinningPass> pass_;  // made on the first frame with animation
};

}  // namespace candela::render
