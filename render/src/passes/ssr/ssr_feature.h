#pragma once
// Screen-space reflections as a frame feature (frames with a glossy opaque surface): the Hi-Z
// pyramid, its pre-integrated visibility, the pre-convolved scene colours, the trace, the
// optional temporal filter (its history owned here) and the composite into the HDR target.
#include <memory>

#include "features/render_feature.h"

namespace candela::render {

class GpuContext;
class SsrPass;
class TemporalHistory;

class SsrFeature final : public RenderFeature {
public:
    explicit SsrFeature(GpuContext& context);
    ~SsrFeature() override;
    bool active(const FeatureFrame& frame) const override;
    void declare(FeatureFrame& frame) override;
    // ssr_ms, ssr_steps_mean, ssr_steps_max, ssr_hit_rate, the rays and the work counter's steps.
    void collectStats(RendererStats& stats, bool declared) const override;
    void restartHistory() override;

private:
    GpuContext& context_;
    std::unique_ptr<SsrPass> pass_;  // made on the first frame with a glossy surface
    std::unique_ptr<TemporalHistory> history_;
};

}  // namespace candela::render
