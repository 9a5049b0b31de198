#pragma once
// Light shafts (Yusov 2014, GPU Pro 5, "High Performance Outdoor Light Scattering Using Epipolar
// Sampling") as a frame feature: the sun's light scattered by the air over the lit frame and its
// medium, under the blended surfaces (frames whose scene has an atmosphere). The aerial
// perspective goes into the frame's IntegratedFroxels for blended surfaces, wires and hair; then
// the epipolar passes (coordinates, tree, march/refine/interpolate, unwarp) or the brute-force
// march over the lit HDR target.
#include <memory>

#include "features/render_feature.h"

namespace candela::render {

class GpuContext;
class ScatteringPass;

class ScatteringFeature final : public RenderFeature {
public:
    explicit ScatteringFeature(GpuContext& context);
    ~ScatteringFeature() override;
    bool active(const FeatureFrame& frame) const override;
    void declare(FeatureFrame& frame) override;
    // scattering_ms, aerial_perspective_ms, scattering_samples and scattering_steps.
    void collectStats(RendererStats& stats, bool declared) const override;

private:
    GpuContext& context_;
    std::unique_ptr<ScatteringPass> pass_;  // made on the first frame with shafts
    bool marched_ = false;                  // the last declared frame marched the air
};

}  // namespace candela::render
