#include "passes/hair/hair_feature.h"

#include <algorithm>
#include <cmath>

#include "candela/render/frame_inputs.h"
#include "features/scene_targets.h"
#include "frame_graph/frame_graph_executor.h"
#include "lit_inputs.h"
#include "passes/hair/hair_pass.h"
#include "passes/shadows/shadow_frame.h"
#include "passes/shadows/shadow_pass.h"
#include "passes/volumetrics/integrated_froxels.h"

namespace candela::render {

HairFeature::HairFeature(GpuContext& context) : context_(context) {}

HairFeature::~HairFeature() = default;

bool HairFeature::active(const FeatureFrame& frame) const {
    return !frame.inputs.scene.hair.empty();
}

void HairFeature::declare(FeatureFrame& frame) {
    drawn_ = false;
    const RendererOptions& options = frame.options;
    if (!pass_) pass_ = std::make_unique<HairPass>(context_);
    if (!pass_->prepare(frame.inputs.scene, frame.lighting, options.hairShading,
                        options.hairSelfShadow)) {
        return;
    }
    frame.features.push_back("hair");
    drawn_ = true;
    FrameGraph& g = frame.graph;
    SceneTargets& targets = frame.board.get<SceneTargets>();
    const LitFrame& lit = frame.board.get<LitFrame>();
    const ShadowFrame* shadows = frame.board.find<ShadowFrame>();
    const IntegratedFroxels* froxels = frame.board.find<IntegratedFroxels>();
    const uint32_t width = frame.width;
    const uint32_t height = frame.height;
    const uint32_t capacity = uint32_t(
        std::min<uint64_t>({uint64_t(std::max(options.hairNodesPerPixel, 1u)) * width * height,
                            1u << 26, HairPass::maxNodes(context_)}));
    nodeCapacity_ = capacity;
    const CameraView& camera = frame.inputs.scene.camera;
    HairPass::Inputs base{};
    base.nodeCapacity = capacity;
    base.pixelRadiusPerDepth = 1.0f / (std::abs(camera.projection[1][1]) * float(height));
    base.nearPlane = camera.nearPlane;
    base.lit = lit.inputs;
    ResourceHandle heads =
        g.createBuffer("hair.heads", HairPass::headBytes(width, height),
                       VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    ResourceHandle nodes = g.createBuffer("hair.nodes", HairPass::nodeBytes(capacity),
                                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    ResourceHandle counters = g.importBuffer("hair.counters", &pass_->counters(), true);
    // Self-shadowing (TressFX): a hair depth map for every shadow view, only in frames where
    // some light has a shadow map.
    const bool selfShadow = frame.lighting.shadows && shadows &&
                            options.hairSelfShadow != HairSelfShadow::Off &&
                            options.hairShading == HairShading::Lit;
    ResourceHandle hairShadow{};
    if (selfShadow) {
        hairShadow =
            g.createImage("hair.shadow_depth",
                          HairPass::hairShadowDepthDesc(shadows->pass->atlas().desc().width));
        frame.features.push_back("hair_self_shadow");
    }
    const ResourceHandle hdr = targets.hdr;
    const ResourceHandle depth = targets.depth;
    const std::optional<ResourceHandle> froxelBuffer = froxels ? froxels->buffer : std::nullopt;
    auto inputsOf = [hdr, depth, base, heads, nodes, selfShadow, hairShadow,
                     froxelBuffer](PassContext& ctx) {
        HairPass::Inputs in = base;
        if (froxelBuffer) {
            in.froxels = true;
            in.froxelIntegrated = ctx.buffer(*froxelBuffer);
        }
        in.selfShadow = selfShadow;
        if (selfShadow) in.hairShadow = ctx.image(hairShadow);
        in.hdr = ctx.image(hdr);
        in.depth = ctx.image(depth);
        in.heads = ctx.buffer(heads);
        in.nodes = ctx.buffer(nodes);
        return in;
    };
    HairPass* pass = pass_.get();
    {
        auto p = g.addPass("hair_clear", PassKind::Device, [pass, inputsOf](PassContext& ctx) {
            pass->recordClear(ctx.cmd(), inputsOf(ctx));
        });
        heads = p.write(heads, Use::TransferDst);
        counters = p.write(counters, Use::TransferDst);
    }
    {
        auto p = g.addPass("hair_fill", PassKind::Device, [pass, inputsOf](PassContext& ctx) {
            pass->recordFill(ctx.cmd(), inputsOf(ctx));
        });
        p.read(targets.depth, Use::DepthRead);
        p.read(targets.camera, Use::Uniform, kRasterStages);
        heads = p.write(heads, Use::StorageReadWrite, kFragmentStage);
        nodes = p.write(nodes, Use::StorageWrite, kFragmentStage);
        counters = p.write(counters, Use::StorageReadWrite, kFragmentStage);
    }
    if (selfShadow) {
        const ShadowPass* shadowPass = shadows->pass;
        auto p = g.addPass(
            "hair_shadow_depth", PassKind::Device, [pass, shadowPass, inputsOf](PassContext& ctx) {
                pass->recordShadowDepth(ctx.cmd(), inputsOf(ctx), shadowPass->views());
            });
        p.read(shadows->views, Use::StorageRead, VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT);
        hairShadow = p.write(hairShadow, Use::DepthWrite);
    }
    {
        auto p = g.addPass("hair_resolve", PassKind::Device, [pass, inputsOf](PassContext& ctx) {
            pass->recordResolve(ctx.cmd(), inputsOf(ctx));
        });
        p.read(targets.camera, Use::Uniform, kRasterStages);
        p.read(heads, Use::StorageRead, kFragmentStage);
        p.read(nodes, Use::StorageRead, kFragmentStage);
        lit.reads.declareReads(p, kFragmentStage);
        if (selfShadow) p.read(hairShadow, Use::Sampled, kFragmentStage);
        if (froxelBuffer) p.read(*froxelBuffer, Use::StorageRead, kFragmentStage);
        targets.hdr = p.write(targets.hdr, Use::ColorAttachment);
    }
    {
        auto p = g.addPass("hair_depth", PassKind::Device, [pass, inputsOf](PassContext& ctx) {
            pass->recordDepth(ctx.cmd(), inputsOf(ctx));
        });
        p.read(targets.camera, Use::Uniform, kRasterStages);
        p.read(heads, Use::StorageRead, kFragmentStage);
        p.read(nodes, Use::StorageRead, kFragmentStage);
        targets.depth = p.write(targets.depth, Use::DepthWrite);
    }
}

void HairFeature::collectStats(RendererStats& stats, bool declared) const {
    stats.hairNodes = 0;
    stats.hairNodesDropped = 0;
    stats.hairNodeCapacity = 0;
    stats.work.hairFragments = 0;
    if (!declared || !drawn_) return;
    stats.hairNodes = pass_->requestedNodes();
    stats.work.hairFragments = stats.hairNodes;
    stats.hairNodeCapacity = nodeCapacity_;
    stats.hairNodesDropped = stats.hairNodes > nodeCapacity_ ? stats.hairNodes - nodeCapacity_ : 0;
}

}  // namespace candela::render
