#pragma once
// Volumetric lighting as a frame feature, over the lit opaque surfaces and the background
// (frames whose scene has a medium): Vos's (GPU Pro 5) per-light volumes (marched at half
// resolution, blurred, upsampled), froxels (lit, integrated, composited by depth) or the
// reference march. Lights the fog's grid of the frame's IntegratedFroxels.
#include <memory>

#include "features/render_feature.h"

namespace candela::render {

class GpuContext;
class VolumetricsPass;

class VolumetricsFeature final : public RenderFeature {
public:
    explicit VolumetricsFeature(GpuContext& context);
    ~VolumetricsFeature() override;
    bool active(const FeatureFrame& frame) const override;
    void declare(FeatureFrame& frame) override;
    // volumetrics_ms.
    void collectStats(RendererStats& stats, bool declared) const override;

private:
    GpuContext& context_;
    std::unique_ptr<VolumetricsPass> pass_;  // made on the first frame with a medium
};

}  // namespace candela::render
