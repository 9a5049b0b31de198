#include "renderer_ao_temporal.h"

#include "candela/render/gpu_image.h"
#include "frame_graph/frame_graph_executor.h"

namespace candela::render {

ResourceHandle declareAoTemporal(FrameGraph& g, const AoTemporalDeclaration& d) {
    const ResourceHandle history = d.history.previous;
    const ResourceHandle written = d.history.written;
    ResourceHandle accumulated =
        g.createImage("ao.accumulated", AmbientOcclusionPass::occlusionDesc(d.width, d.height));
    auto p = g.addPass("ambient_occlusion_temporal", PassKind::Device,
                       [d, history, written, accumulated](PassContext& ctx) {
                           AmbientOcclusionPass::Inputs in = d.aoInputs;
                           in.depth = ctx.image(d.depth);
                           in.normalRoughMetal = ctx.image(d.normal);
                           const AmbientOcclusionPass::TemporalInputs temporal{
                               ctx.image(d.current), ctx.image(d.motion), ctx.image(history),
                               d.history.valid, d.maxFrames};
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
