// The renderer's GPU-side measurements of a recorded frame (Renderer::collectStats): pass
// times, light assignment and the lighting pass's light pair counts; each feature adds its own
// (RenderFeature::collectStats).

#include <cstdint>

#include "candela/render/renderer.h"
#include "clustered/cluster_light_lists.h"
#include "features/declared_frame.h"
#include "features/feature_list.h"
#include "frame_graph/frame_graph_executor.h"
#include "lit_scene.h"
#include "passes/lighting/lighting_pass.h"
#include "passes/nonfinite/nonfinite_guard.h"

namespace candela::render {

const RendererStats& Renderer::collectStats() {
    stats_.lightingMs = 0.0;
    stats_.skyMs = 0.0;
    stats_.shadowMs = 0.0;
    stats_.passMs.clear();
    const DeclaredFrame& declared = *frame_;
    if (declared.recorded == RecordedFrame::None) {
        features_->collectStats(stats_, false);
        return stats_;
    }
    nonFinite_->collect(executor_->compiled().order, stats_);
    ClusterLightLists& clusters = lit_->clusters();
    const bool onDevice = clusters.assignedOnDevice();
    clusters.collectStats(stats_);
    stats_.passMs = executor_->passTimes();
    if (onDevice) stats_.lightAssignMs = passMilliseconds(stats_, "light_assign_");
    stats_.skyMs = passMilliseconds(stats_, "atmosphere_");
    for (const auto& [name, ms] : stats_.passMs) {
        if (name == "lighting") stats_.lightingMs = ms;
        if (name == "shadows") stats_.shadowMs = ms;
        if (name == "sky_occlusion") stats_.skyOcclusionMs = ms;  // kept until the next build
    }
    // Work the frame's declaration fixed (froxel pairs, AO samples), then the passes' counters:
    // the features' (SSR steps...), then the lighting pass's.
    stats_.work = declared.work;
    features_->collectStats(stats_, true);
    stats_.lightEvaluations = 0;
    stats_.litPairs = 0;
    if (options_.countLightPairs && declared.recorded == RecordedFrame::Scene) {
        const auto* counts = static_cast<const uint32_t*>(targets_.pairCounts.mapped());
        const uint32_t n = LightingPass::kCountsPerWorkgroup;
        for (uint32_t g = 0; g < LightingPass::workgroupCount(targets_.width, targets_.height);
             ++g) {
            const uint32_t* c = counts + size_t(g) * n;
            stats_.lightEvaluations += c[0];
            stats_.litPairs += c[1];
            stats_.work.lightEvaluationsPlain += c[2];
            stats_.work.lightEvaluationsArea += c[3];
            stats_.work.lightEvaluationsShadowed += c[4];
            stats_.work.shadowFilterTaps += c[5];
            stats_.work.shadowBlockerTaps += c[6];
        }
    }
    return stats_;
}

}  // namespace candela::render
