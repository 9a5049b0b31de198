// Non-finite radiance: every checked frame counts the NaN and Inf pixels of its scene radiance
// before tonemapping (RendererStats::nonFinitePixels); a frame after one that had some probes
// each float image every pass writes and names the first pass that wrote one
// (RendererStats::nonFiniteSource), so a bad frame is never silent and never anonymous.
#include <string>

#include "candela/render/renderer.h"
#include "frame_graph/frame_graph.h"
#include "frame_graph/frame_graph_executor.h"
#include "passes/nonfinite/nonfinite_pass.h"
#include "passes/nonfinite/nonfinite_probes.h"

namespace candela::render {

void Renderer::declareNonFiniteCheck(ResourceHandle hdr) {
    FrameGraph& g = *graph_;
    if (!nonFinitePass_) nonFinitePass_ = std::make_unique<NonFinitePass>(context_);
    nonFinitePass_->clear();
    nonFiniteChecked_ = true;
    const ResourceHandle count = g.importBuffer("nonfinite.frame", &nonFinitePass_->counts(), true);
    auto p = g.addPass("nonfinite_check", PassKind::Device, [this, hdr](PassContext& ctx) {
        nonFinitePass_->recordRadianceCount(ctx.cmd(), ctx.image(hdr));
    });
    p.read(hdr, Use::StorageRead);
    p.write(count, Use::StorageReadWrite);
    p.sideEffect();
}

void Renderer::addNonFiniteProbes() {
    nonFiniteProbes_.clear();
    if (!diagnoseNonFinite_ || !nonFinitePass_) return;
    diagnoseNonFinite_ = false;
    features_.push_back("nonfinite_probes");
    nonFiniteProbes_ = render::addNonFiniteProbes(
        *graph_, *nonFinitePass_, NonFinitePass::kRadianceSlot + 1, NonFinitePass::kSlots);
}

void Renderer::collectNonFinite() {
    stats_.nonFinitePixels = 0;
    stats_.nonFiniteSource.clear();
    if (!nonFiniteChecked_) return;
    stats_.nonFinitePixels = nonFinitePass_->count(NonFinitePass::kRadianceSlot);
    if (nonFiniteProbes_.empty()) return;
    std::vector<uint32_t> counts;
    counts.reserve(nonFiniteProbes_.size());
    for (const NonFiniteProbe& probe : nonFiniteProbes_)
        counts.push_back(nonFinitePass_->count(probe.slot));
    const NonFiniteProbe* first =
        firstNonFiniteProbe(nonFiniteProbes_, counts, executor_->compiled().order);
    if (first) {
        stats_.nonFiniteSource =
            "pass '" + first->passName + "' (image '" + first->imageName + "', " +
            std::to_string(counts[size_t(first - &nonFiniteProbes_[0])]) + " texels)";
    } else {
        stats_.nonFiniteSource =
            "no pass's float image held one in this frame (it came through a buffer or a copy, "
            "or this frame did not repeat it)";
    }
}

}  // namespace candela::render
