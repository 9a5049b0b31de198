#pragma once
// Automatic exposure as a frame feature (--exposure auto): each frame meters the luminance
// histogram the frame before wrote (read back once that frame completed) and adapts towards it
// (auto_exposure.h); its passes write this frame's histogram of the HDR target after the
// antialiasing resolve and before bloom.
#include <memory>
#include <optional>

#include "candela/render/gpu_buffer.h"
#include "features/render_feature.h"

namespace candela::render {

class GpuContext;
class ExposureHistogramPass;
struct FrameInputs;

class AutoExposureFeature final : public RenderFeature {
public:
    explicit AutoExposureFeature(GpuContext& context);
    ~AutoExposureFeature() override;
    bool active(const FeatureFrame& frame) const override;
    // This frame's EV100: the adapted one, or the camera's until something is metered. Writes
    // stats.exposureEv100 (metered) and stats.adaptedEv100.
    float ev100(const FrameInputs& inputs, const AutoExposureSettings& settings,
                RendererStats& stats);
    void declare(FeatureFrame& frame) override;
    // Adaptation starts again from the next metered frame.
    void restartHistory() override { adaptedEv100_.reset(); }

private:
    GpuContext& context_;
    std::unique_ptr<ExposureHistogramPass> pass_;
    GpuBuffer histogram_;  // host-visible: read back at the start of the next frame
    bool histogramWritten_ = false;
    std::optional<float> adaptedEv100_;  // unset until the first metered frame
};

}  // namespace candela::render
