#include "passes/skinning/skinning_feature.h"

#include "candela/render/frame_inputs.h"
#include "frame_graph/frame_graph_executor.h"
#include "passes/skinning/skinning_pass.h"

namespace candela::render {

SkinningFeature::SkinningFeature(GpuContext& context) : context_(context) {}

SkinningFeature::~SkinningFeature() = default;

bool SkinningFeature::active(const FeatureFrame& frame) const {
    return !frame.inputs.scene.deforms.empty();
}

void SkinningFeature::declare(FeatureFrame& frame) {
    if (!pass_) pass_ = std::make_unique<SkinningPass>(context_);
    const FrameScene& scene = frame.inputs.scene;
    pass_->upload(scene.jointMatrices, scene.morphWeights);
    FrameGraph& g = frame.graph;
    ResourceHandle deformed = g.importBuffer("deformed_vertices", nullptr);
    const ResourceHandle joints = g.importBuffer("skinning.joints", &pass_->jointBuffer());
    const ResourceHandle weights =
        g.importBuffer("skinning.morph_weights", &pass_->morphWeightBuffer());
    const SkinningPass* pass = pass_.get();
    SceneResources* resources = &frame.resources;
    auto p = g.addPass("skinning", PassKind::Device, [pass, &scene, resources](PassContext& ctx) {
        pass->record(ctx.cmd(), scene, *resources);
    });
    p.read(joints, Use::StorageRead);
    p.read(weights, Use::StorageRead);
    frame.board.put(DeformedVertices{p.write(deformed, Use::StorageWrite)});
}

void SkinningFeature::collectStats(RendererStats& stats, bool) const {
    stats.skinningMs = passMilliseconds(stats, "skinning");
}

}  // namespace candela::render
