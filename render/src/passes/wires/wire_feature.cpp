#include "passes/wires/wire_feature.h"

#include <cmath>
#include <optional>

#include "candela/render/frame_inputs.h"
#include "features/scene_targets.h"
#include "frame_graph/frame_graph_executor.h"
#include "lit_inputs.h"
#include "passes/volumetrics/integrated_froxels.h"
#include "passes/wires/wire_pass.h"

namespace candela::render {

WireFeature::WireFeature(GpuContext& context) : context_(context) {}

WireFeature::~WireFeature() = default;

bool WireFeature::active(const FeatureFrame& frame) const {
    return !frame.inputs.scene.wires.empty();
}

void WireFeature::declare(FeatureFrame& frame) {
    if (!pass_) pass_ = std::make_unique<WirePass>(context_);
    if (!pass_->prepare(frame.inputs.scene, frame.lighting, frame.options.wires)) return;
    frame.features.push_back("wires");
    SceneTargets& targets = frame.board.get<SceneTargets>();
    const LitFrame& lit = frame.board.get<LitFrame>();
    const IntegratedFroxels* froxels = frame.board.find<IntegratedFroxels>();
    const CameraView& camera = frame.inputs.scene.camera;
    WirePass::Inputs base{};
    base.lit = lit.inputs;
    base.pixelRadiusPerDepth = 1.0f / (std::abs(camera.projection[1][1]) * float(frame.height));
    base.nearPlane = camera.nearPlane;
    const ResourceHandle hdr = targets.hdr;
    const ResourceHandle depth = targets.depth;
    const std::optional<ResourceHandle> froxelBuffer = froxels ? froxels->buffer : std::nullopt;
    const WirePass* pass = pass_.get();
    auto p = frame.graph.addPass("wires", PassKind::Device,
                                 [pass, base, hdr, depth, froxelBuffer](PassContext& ctx) {
                                     WirePass::Inputs in = base;
                                     in.hdr = ctx.image(hdr);
                                     in.depth = ctx.image(depth);
                                     if (froxelBuffer) {
                                         in.froxels = true;
                                         in.froxelIntegrated = ctx.buffer(*froxelBuffer);
                                     }
                                     pass->record(ctx.cmd(), in);
                                 });
    p.read(targets.depth, Use::DepthRead);
    p.read(targets.camera, Use::Uniform, kRasterStages);
    lit.reads.declareReads(p, kFragmentStage);
    if (froxelBuffer) p.read(*froxelBuffer, Use::StorageRead, kFragmentStage);
    targets.hdr = p.write(targets.hdr, Use::ColorAttachment);
}

}  // namespace candela::render
