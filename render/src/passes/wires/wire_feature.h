#pragma once
// Wires (Persson 2014, GPU Pro 5, "Wire Antialiasing") as a frame feature: over the lit frame
// and its medium, under the blended surfaces. Reads the scene targets, the lit inputs and the
// froxels from the blackboard.
#include <memory>

#include "features/render_feature.h"

namespace candela::render {

class GpuContext;
class WirePass;

class WireFeature final : public RenderFeature {
public:
    explicit WireFeature(GpuContext& context);
    ~WireFeature() override;
    bool active(const FeatureFrame& frame) const override;
    void declare(FeatureFrame& frame) override;

private:
    GpuContext& context_;
    std::unique_ptr<WirePass> pass_;  // made for the first frame with wires
};

}  // namespace candela::render
