#pragma once
// Geometric antialiasing as a frame feature (--aa gbaa; render/README.md "GBAA"): after the
// scene's passes, where TAA would resolve, the HDR target is blended across the edges the
// G-buffer pass wrote (GBufferFrame::edges) into a transient and copied back, so exposure,
// bloom, tonemapping and the .exr capture see the antialiased radiance.
#include <memory>

#include "features/render_feature.h"

namespace candela::render {

class GpuContext;
class GbaaPass;

class GbaaFeature final : public RenderFeature {
public:
    explicit GbaaFeature(GpuContext& context);
    ~GbaaFeature() override;
    bool active(const FeatureFrame& frame) const override;
    void declare(FeatureFrame& frame) override;

private:
    GpuContext& context_;
    std::unique_ptr<GbaaPass> pass_;
};

}  // namespace candela::render
