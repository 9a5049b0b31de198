// The renderer's GPU-side measurements of a recorded frame (Renderer::collectStats): pass
// times summed per feature, light assignment, hair nodes, SSR and light-shaft counters, and
// the lighting pass's light pair counts.

#include <cstdint>

#include "candela/render/renderer.h"
#include "clustered/cluster_light_lists.h"
#include "features/render_feature.h"
#include "frame_graph/frame_graph_executor.h"
#include "passes/lighting/lighting_pass.h"
#include "passes/nonfinite/nonfinite_guard.h"

namespace candela::render {

const RendererStats& Renderer::collectStats() {
    stats_.lightingMs = 0.0;
    stats_.taaMs = 0.0;
    stats_.bloomMs = 0.0;
    stats_.skinningMs = 0.0;
    stats_.aoMs = 0.0;
    stats_.volumetricsMs = 0.0;
    stats_.skyMs = 0.0;
    stats_.scatteringMs = 0.0;
    stats_.scatteringSamples = 0;
    stats_.scatteringSteps = 0;
    stats_.aerialPerspectiveMs = 0.0;
    stats_.shadowMs = 0.0;
    stats_.ssrMs = 0.0;
    stats_.ssrStepsMean = 0.0;
    stats_.ssrStepsMax = 0;
    stats_.ssrHitRate = 0.0;
    stats_.ssrRays = 0;
    stats_.passMs.clear();
    if (!frameRecorded_) return stats_;
    nonFinite_->collect(executor_->compiled().order, stats_);
    const bool onDevice = clusters_->assignedOnDevice();
    clusters_->collectStats(stats_);
    if (onDevice) stats_.lightAssignMs = 0.0;
    stats_.passMs = executor_->passTimes();
    for (const auto& [name, ms] : stats_.passMs) {
        if (name == "lighting") stats_.lightingMs = ms;
        if (name == "taa" || name == "taa_copy") stats_.taaMs += ms;
        if (name.starts_with("bloom_")) stats_.bloomMs += ms;
        if (name == "skinning") stats_.skinningMs += ms;
        if (name.starts_with("ambient_occlusion_")) stats_.aoMs += ms;
        if (name.starts_with("volumetrics_")) stats_.volumetricsMs += ms;
        if (name.starts_with("atmosphere_")) stats_.skyMs += ms;
        if (name.starts_with("scattering_")) stats_.scatteringMs += ms;
        if (name == "aerial_perspective") stats_.aerialPerspectiveMs += ms;
        if (name == "shadows") stats_.shadowMs = ms;
        if (name == "sky_occlusion") stats_.skyOcclusionMs = ms;  // kept until the next build
        if (name.starts_with("ssr_")) stats_.ssrMs += ms;
        if (onDevice && name.starts_with("light_assign_")) stats_.lightAssignMs += ms;
    }
    // Work the frame's declaration fixed (froxel pairs, AO samples), then the passes' counters:
    // the features' (SSR steps...), then the lighting pass's.
    stats_.work = declaredWork_;
    for (size_t i = 0; i < renderFeatures_.size(); ++i)
        renderFeatures_[i]->collectStats(stats_, featureDeclared_[i]);
    stats_.lightEvaluations = 0;
    stats_.litPairs = 0;
    stats_.work.scatteringSteps = stats_.scatteringSteps;
    stats_.work.hairFragments = stats_.hairNodes;
    if (options_.countLightPairs && !features_.empty() && features_[0] != "test_triangle") {
        const auto* counts = static_cast<const uint32_t*>(pairCounts_.mapped());
        const uint32_t n = LightingPass::kCountsPerWorkgroup;
        for (uint32_t g = 0; g < LightingPass::workgroupCount(width_, height_); ++g) {
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
