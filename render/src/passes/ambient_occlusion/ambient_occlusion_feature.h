#pragma once
// Ambient occlusion as a frame feature, between the G-buffer and lighting: GTAO (Jimenez et al.
// 2016, "Practical Realtime Strategies for Accurate Indirect Occlusion"), its denoise and its
// temporal accumulation (the history owned here), or the ray-marched reference. Publishes an
// AmbientOcclusionFrame for the lighting pass and SSR. Frames without AO declare nothing.
#include <cstdint>
#include <memory>

#include "features/render_feature.h"

namespace candela::render {

class AmbientOcclusionPass;
class GpuContext;
class TemporalHistory;

class AmbientOcclusionFeature final : public RenderFeature {
public:
    explicit AmbientOcclusionFeature(GpuContext& context);
    ~AmbientOcclusionFeature() override;
    bool active(const FeatureFrame& frame) const override;
    void declare(FeatureFrame& frame) override;
    // ao_ms.
    void collectStats(RendererStats& stats, bool declared) const override;
    void restartHistory() override;

    // Whether GTAO accumulates over frames with these options (AoTemporal: with TAA, always or
    // never).
    static bool accumulates(const RendererOptions& options);

private:
    GpuContext& context_;
    std::unique_ptr<AmbientOcclusionPass> pass_;  // made on the first frame with AO
    std::unique_ptr<TemporalHistory> history_;
    uint32_t frame_ = 0;  // accumulated frames: the slices' rotation
};

}  // namespace candela::render
