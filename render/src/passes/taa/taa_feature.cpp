#include "passes/taa/taa_feature.h"

#include "features/frame_exposure.h"
#include "features/scene_targets.h"
#include "frame_graph/frame_graph_executor.h"
#include "frame_graph/image_copy_pass.h"
#include "passes/taa/taa_pass.h"
#include "temporal_history.h"

namespace candela::render {

TaaFeature::TaaFeature(GpuContext& context)
    : context_(context), history_(std::make_unique<TemporalHistory>()) {}

TaaFeature::~TaaFeature() = default;

bool TaaFeature::active(const FeatureFrame& frame) const {
    return frame.options.aa == AntiAliasing::Taa;
}

void TaaFeature::declare(FeatureFrame& frame) {
    frame.features.push_back("taa");
    if (!pass_) pass_ = std::make_unique<TaaPass>(context_);
    // RGBA32F like the target it is copied into; alpha counts the samples it holds.
    history_->ensure(context_,
                     {VK_FORMAT_R32G32B32A32_SFLOAT, frame.width, frame.height, 1, false,
                      VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                          VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT},
                     16);
    FrameGraph& g = frame.graph;
    SceneTargets& targets = frame.board.get<SceneTargets>();
    const TemporalHistory::Frame history = history_->declare(g, "taa.history", "taa.resolved");
    ResourceHandle resolved = history.written;
    const ResourceHandle hdr = targets.hdr;
    const ResourceHandle motion = targets.motion;
    const RendererOptions& options = frame.options;
    const TaaPass::Settings settings{frame.board.get<FrameExposure>().exposure,
                                     options.taaMinimumBlend, history.valid, options.taaSharpness};
    {
        const TaaPass* pass = pass_.get();
        auto p = g.addPass(
            "taa", PassKind::Device,
            [pass, hdr, motion, previous = history.previous, resolved, settings](PassContext& ctx) {
                pass->recordResolve(ctx.cmd(), ctx.image(hdr), ctx.image(motion),
                                    ctx.image(previous), ctx.image(resolved), settings);
            });
        p.read(hdr, Use::StorageRead);
        p.read(motion, Use::Sampled);
        p.read(history.previous, Use::Sampled);
        resolved = p.write(resolved, Use::StorageWrite);
    }
    targets.hdr = declareImageCopy(g, "taa_copy", resolved, hdr);
}

void TaaFeature::restartHistory() {
    history_->invalidate();
}

void TaaFeature::collectStats(RendererStats& stats, bool) const {
    stats.taaMs = passMilliseconds(stats, "taa");
}

}  // namespace candela::render
