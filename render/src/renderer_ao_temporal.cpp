#include "renderer_ao_temporal.h"

#include "candela/render/gpu_image.h"
#include "frame_graph/frame_graph_executor.h"

namespace candela::render {

ResourceHandle declareAoTemporal(FrameGraph& g, const AoTemporalDeclaration& d) {
    // As TAA's history: last frame's image is read in the state it was left in, the other's
    // contents are discarded and rewritten.
    constexpr ImageState kSampledByCompute{VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                           VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                           VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};
    constexpr ImageState kDiscard{VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                  0};
    const ResourceHandle history =
        g.importImage("ao.history", d.readHistory, kSampledByCompute, ImageState{});
    ResourceHandle written =
        g.importImage("ao.history_written", d.writeHistory, kDiscard, kSampledByCompute);
    ResourceHandle accumulated =
        g.createImage("ao.accumulated", AmbientOcclusionPass::occlusionDesc(d.width, d.height));
    auto p = g.addPass("ambient_occlusion_temporal", PassKind::Device,
                       [d, history, written, accumulated](PassContext& ctx) {
                           AmbientOcclusionPass::Inputs in = d.aoInputs;
                           in.depth = ctx.image(d.depth);
                           in.normalRoughMetal = ctx.image(d.normal);
                           const AmbientOcclusionPass::TemporalInputs temporal{
                               ctx.image(d.current), ctx.image(d.motion), ctx.image(history),
                               d.historyValid, d.maxFrames};
                           d.pass->recordTemporal(ctx.cmd(), in, temporal, ctx.image(accumulated),
                                                  ctx.image(written));
                       });
    p.read(d.depth, Use::Sampled);
    p.read(d.normal, Use::Sampled);
    p.read(d.current, Use::Sampled);
    p.read(d.motion, Use::Sampled);
    p.read(history, Use::Sampled);
    p.read(d.camera, Use::Uniform);
    p.write(written, Use::StorageWrite);
    accumulated = p.write(accumulated, Use::StorageWrite);
    return accumulated;
}

}  // namespace candela::render
