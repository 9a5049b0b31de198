#pragma once
// Temporal antialiasing as a frame feature (--aa taa): after the scene's passes, the HDR target
// resolved against last frame's history (its ping-pong owned here) into this frame's, then
// copied back, so exposure, bloom, tonemapping and captures see the resolved radiance.
#include <memory>

#include "features/render_feature.h"

namespace candela::render {

class GpuContext;
class TaaPass;
class TemporalHistory;

class TaaFeature final : public RenderFeature {
public:
    explicit TaaFeature(GpuContext& context);
    ~TaaFeature() override;
    bool active(const FeatureFrame& frame) const override;
    void declare(FeatureFrame& frame) override;
    // taa_ms (the resolve and its copy back).
    void collectStats(RendererStats& stats, bool declared) const override;
    void restartHistory() override;

private:
    GpuContext& context_;
    std::unique_ptr<TaaPass> pass_;
    std::unique_ptr<TemporalHistory> history_;
};

}  // namespace candela::render
