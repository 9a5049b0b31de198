#pragma once
// Bloom as a frame feature (--bloom above 0): the HDR target's downsampled pyramid, composited
// back onto it in place, before tonemapping.
#include <memory>

#include "features/render_feature.h"

namespace candela::render {

class GpuContext;
class BloomPass;

class BloomFeature final : public RenderFeature {
public:
    explicit BloomFeature(GpuContext& context);
    ~BloomFeature() override;
    bool active(const FeatureFrame& frame) const override;
    void declare(FeatureFrame& frame) override;
    // bloom_ms.
    void collectStats(RendererStats& stats, bool declared) const override;

private:
    GpuContext& context_;
    std::unique_ptr<BloomPass> pass_;
};

}  // namespace candela::render
