#include "passes/nonfinite/nonfinite_guard.h"

#include <string>

#include "frame_graph/frame_graph_executor.h"
#include "passes/nonfinite/nonfinite_pass.h"

namespace candela::render {

NonFiniteGuard::NonFiniteGuard(GpuContext& context) : context_(context) {}

NonFiniteGuard::~NonFiniteGuard() = default;

void NonFiniteGuard::declareCheck(FrameGraph& graph, ResourceHandle hdr) {
    if (!pass_) pass_ = std::make_unique<NonFinitePass>(context_);
    pass_->clear();
    checked_ = true;
    const ResourceHandle count = graph.importBuffer("nonfinite.frame", &pass_->counts(), true);
    const NonFinitePass* pass = pass_.get();
    auto p = graph.addPass("nonfinite_check", PassKind::Device, [pass, hdr](PassContext& ctx) {
        pass->recordRadianceCount(ctx.cmd(), ctx.image(hdr));
    });
    p.read(hdr, Use::StorageRead);
    p.write(count, Use::StorageReadWrite);
    p.sideEffect();
}

bool NonFiniteGuard::declareProbes(FrameGraph& graph) {
    probes_.clear();
    if (!diagnose_ || !pass_) return false;
    diagnose_ = false;
    probes_ =
        addNonFiniteProbes(graph, *pass_, NonFinitePass::kRadianceSlot + 1, NonFinitePass::kSlots);
    return true;
}

void NonFiniteGuard::collect(const std::vector<uint32_t>& executionOrder,
                             RendererStats& stats) const {
    stats.nonFinitePixels = 0;
    stats.nonFiniteSource.clear();
    if (!checked_) return;
    stats.nonFinitePixels = pass_->count(NonFinitePass::kRadianceSlot);
    if (probes_.empty()) return;
    std::vector<uint32_t> counts;
    counts.reserve(probes_.size());
    for (const NonFiniteProbe& probe : probes_)
        counts.push_back(pass_->count(probe.slot));
    const NonFiniteProbe* first = firstNonFiniteProbe(probes_, counts, executionOrder);
    if (first) {
        stats.nonFiniteSource = "pass '" + first->passName + "' (image '" + first->imageName +
                                "', " + std::to_string(counts[size_t(first - &probes_[0])]) +
                                " texels)";
    } else {
        stats.nonFiniteSource =
            "no pass's float image held one in this frame (it came through a buffer or a copy, "
            "or this frame did not repeat it)";
    }
}

}  // namespace candela::render
