#include "passes/gbaa/gbaa_feature.h"

#include "features/gbuffer_frame.h"
#include "features/scene_targets.h"
#include "frame_graph/frame_graph_executor.h"
#include "frame_graph/image_copy_pass.h"
#include "passes/gbaa/gbaa_pass.h"

namespace candela::render {

GbaaFeature::GbaaFeature(GpuContext& context) : context_(context) {}

GbaaFeature::~GbaaFeature() = default;

bool GbaaFeature::active(const FeatureFrame& frame) const {
    return frame.options.aa == AntiAliasing::Gbaa;
}

void GbaaFeature::declare(FeatureFrame& frame) {
    frame.features.push_back("gbaa");
    if (!pass_) pass_ = std::make_unique<GbaaPass>(context_);
    FrameGraph& g = frame.graph;
    SceneTargets& targets = frame.board.get<SceneTargets>();
    const ResourceHandle hdr = targets.hdr;
    const ResourceHandle edges = *frame.board.get<GBufferFrame>().edges;
    ResourceHandle resolved = g.createImage(
        "gbaa.resolved", {VK_FORMAT_R32G32B32A32_SFLOAT, frame.width, frame.height, 1, false,
                          VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT});
    {
        const GbaaPass* pass = pass_.get();
        auto p =
            g.addPass("gbaa", PassKind::Device, [pass, hdr, edges, resolved](PassContext& ctx) {
                pass->recordResolve(ctx.cmd(), ctx.image(hdr), ctx.image(edges),
                                    ctx.image(resolved));
            });
        p.read(hdr, Use::StorageRead);
        p.read(edges, Use::Sampled);
        resolved = p.write(resolved, Use::StorageWrite);
    }
    targets.hdr = declareImageCopy(g, "gbaa_copy", resolved, hdr);
}

}  // namespace candela::render
