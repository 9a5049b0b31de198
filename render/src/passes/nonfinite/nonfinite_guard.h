#pragma once
// Non-finite radiance, guarded: every checked frame counts the NaN and Inf pixels of its scene
// radiance before tonemapping (RendererStats::nonFinitePixels); a frame asked to diagnose probes
// each float image every pass writes and names the first pass that wrote one
// (RendererStats::nonFiniteSource), so a bad frame is never silent and never anonymous.
#include <cstdint>
#include <memory>
#include <vector>

#include "candela/render/renderer_options.h"
#include "frame_graph/frame_graph.h"
#include "passes/nonfinite/nonfinite_probes.h"

namespace candela::render {

class GpuContext;
class NonFinitePass;

class NonFiniteGuard {
public:
    explicit NonFiniteGuard(GpuContext& context);
    ~NonFiniteGuard();
    NonFiniteGuard(const NonFiniteGuard&) = delete;
    NonFiniteGuard& operator=(const NonFiniteGuard&) = delete;

    // The next frame probes its passes (after one whose count was not 0).
    void diagnoseNextFrame() { diagnose_ = true; }
    // Whether this frame checks its radiance: every frame when asked to, and a diagnosis frame.
    bool checks(bool everyFrame) const { return everyFrame || diagnose_; }
    // The count over `hdr` (the scene's radiance before tonemapping), or none this frame.
    void declareCheck(FrameGraph& graph, ResourceHandle hdr);
    void skipCheck() { checked_ = false; }
    // After every other pass is declared: a diagnosis frame's probes. True when it added them.
    bool declareProbes(FrameGraph& graph);
    // After the frame completed; `executionOrder`: the compiled graph's order.
    void collect(const std::vector<uint32_t>& executionOrder, RendererStats& stats) const;

private:
    GpuContext& context_;
    std::unique_ptr<NonFinitePass> pass_;  // made on the first checked frame
    bool checked_ = false;                 // this frame declared the check
    bool diagnose_ = false;                // the next frame probes its passes
    std::vector<NonFiniteProbe> probes_;   // this frame's probes (diagnosis)
};

}  // namespace candela::render
