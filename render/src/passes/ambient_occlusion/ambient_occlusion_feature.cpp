#include "passes/ambient_occlusion/ambient_occlusion_feature.h"

#include <algorithm>
#include <optional>

#include "candela/render/frame_inputs.h"
#include "features/gbuffer_frame.h"
#include "features/scene_targets.h"
#include "frame_graph/frame_graph_executor.h"
#include "lit_inputs.h"
#include "passes/ambient_occlusion/ambient_occlusion_frame.h"
#include "passes/ambient_occlusion/ambient_occlusion_pass.h"
#include "temporal_history.h"

namespace candela::render {

namespace {

// GTAO's temporal accumulation after its denoise (ao_temporal.comp): reads the history written
// last frame, writes the other; returns the accumulated occlusion.
ResourceHandle declareTemporal(FrameGraph& g, const AmbientOcclusionPass* pass,
                               const AmbientOcclusionPass::Inputs& aoInputs,
                               const SceneTargets& targets, ResourceHandle normal,
                               ResourceHandle current, const TemporalHistory::Frame& history,
                               uint32_t maxFrames, uint32_t width, uint32_t height) {
    ResourceHandle accumulated =
        g.createImage("ao.accumulated", AmbientOcclusionPass::occlusionDesc(width, height));
    const ResourceHandle depth = targets.depth;
    const ResourceHandle motion = targets.motion;
    auto p = g.addPass("ambient_occlusion_temporal", PassKind::Device,
                       [pass, aoInputs, depth, normal, current, motion, history, maxFrames,
                        accumulated](PassContext& ctx) {
                           AmbientOcclusionPass::Inputs in = aoInputs;
                           in.depth = ctx.image(depth);
                           in.normalRoughMetal = ctx.image(normal);
                           const AmbientOcclusionPass::TemporalInputs temporal{
                               ctx.image(current), ctx.image(motion), ctx.image(history.previous),
                               history.valid, maxFrames};
                           pass->recordTemporal(ctx.cmd(), in, temporal, ctx.image(accumulated),
                                                ctx.image(history.written));
                       });
    p.read(depth, Use::Sampled);
    p.read(normal, Use::Sampled);
    p.read(current, Use::Sampled);
    p.read(motion, Use::Sampled);
    p.read(history.previous, Use::Sampled);
    p.read(targets.camera, Use::Uniform);
    p.write(history.written, Use::StorageWrite);
    return p.write(accumulated, Use::StorageWrite);
}

}  // namespace

AmbientOcclusionFeature::AmbientOcclusionFeature(GpuContext& context)
    : context_(context), history_(std::make_unique<TemporalHistory>()) {}

AmbientOcclusionFeature::~AmbientOcclusionFeature() = default;

bool AmbientOcclusionFeature::accumulates(const RendererOptions& options) {
    if (options.ao != AoMode::Gtao) return false;
    switch (options.aoSettings.temporal) {
        case AoTemporal::WithTaa:
            return options.aa == AntiAliasing::Taa;
        case AoTemporal::Always:
            return true;
        case AoTemporal::Never:
            break;
    }
    return false;
}

bool AmbientOcclusionFeature::active(const FeatureFrame& frame) const {
    return frame.options.ao != AoMode::Off || frame.lighting.ao != AoMode::Off;
}

void AmbientOcclusionFeature::declare(FeatureFrame& frame) {
    const AoMode mode = frame.lighting.ao;
    if (mode != AoMode::Gtao) history_->invalidate();  // the sequence broke
    if (mode == AoMode::Off) return;                   // no sky this frame: nothing to occlude
    if (!pass_) pass_ = std::make_unique<AmbientOcclusionPass>(context_);
    const AmbientOcclusionPass* pass = pass_.get();
    const RendererOptions& options = frame.options;
    const FrameScene& scene = frame.inputs.scene;
    FrameGraph& g = frame.graph;
    const uint32_t width = frame.width;
    const uint32_t height = frame.height;
    const SceneTargets& targets = frame.board.get<SceneTargets>();
    AmbientOcclusionPass::Inputs aoInputs{
        {}, {}, frame.board.get<LitFrame>().inputs.camera, options.aoSettings};
    aoInputs.settings.radius = std::max(scene.aoRadius, 1e-3f);
    aoInputs.settings.intensity = scene.aoIntensity;
    // Temporal accumulation rotates the slices every frame; without it they stay put, so a
    // single frame (and every golden) is what it always was.
    const bool accumulate = mode == AoMode::Gtao && accumulates(options);
    if (accumulate) aoInputs.frameRotation = AmbientOcclusionPass::frameRotation(frame_++);
    const ResourceHandle depth = targets.depth;
    const ResourceHandle normal = frame.board.get<GBufferFrame>().color[1];
    auto declareInputs = [&](FrameGraph::PassBuilder& p) {
        p.read(depth, Use::Sampled);
        p.read(normal, Use::Sampled);
        p.read(targets.camera, Use::Uniform);
    };
    AmbientOcclusionFrame out;
    out.mode = mode == AoMode::Gtao && frame.lighting.aoSpecularFromHorizons ? 3u : uint32_t(mode);
    out.intensity = std::clamp(scene.aoIntensity, 0.0f, 1.0f);
    ResourceHandle raw =
        g.createImage("ao.raw", AmbientOcclusionPass::occlusionDesc(width, height));
    ResourceHandle specular =
        g.createImage("ao.specular", AmbientOcclusionPass::specularDesc(width, height));
    if (mode == AoMode::Gtao) {
        // Each pixel takes `steps` depth samples on both sides of each slice.
        frame.work.aoSamples =
            uint64_t(width) * height * options.aoSettings.slices * 2u * options.aoSettings.steps;
        auto p = g.addPass("ambient_occlusion_gtao", PassKind::Device,
                           [pass, depth, normal, raw, specular, aoInputs](PassContext& ctx) {
                               AmbientOcclusionPass::Inputs in = aoInputs;
                               in.depth = ctx.image(depth);
                               in.normalRoughMetal = ctx.image(normal);
                               pass->recordGtao(ctx.cmd(), in, ctx.image(raw), ctx.image(specular));
                           });
        declareInputs(p);
        raw = p.write(raw, Use::StorageWrite);
        out.specular = p.write(specular, Use::StorageWrite);
        ResourceHandle filtered =
            g.createImage("ao.filtered", AmbientOcclusionPass::occlusionDesc(width, height));
        auto d =
            g.addPass("ambient_occlusion_denoise", PassKind::Device,
                      [pass, depth, normal, raw, filtered, aoInputs](PassContext& ctx) {
                          AmbientOcclusionPass::Inputs in = aoInputs;
                          in.depth = ctx.image(depth);
                          in.normalRoughMetal = ctx.image(normal);
                          pass->recordDenoise(ctx.cmd(), in, ctx.image(raw), ctx.image(filtered));
                      });
        declareInputs(d);
        d.read(raw, Use::Sampled);
        out.occlusion = d.write(filtered, Use::StorageWrite);
        if (accumulate) {
            frame.features.push_back("ao_temporal");
            history_->ensure(context_, AmbientOcclusionPass::historyDesc(width, height), 16);
            out.occlusion =
                declareTemporal(g, pass, aoInputs, targets, normal, *out.occlusion,
                                history_->declare(g, "ao.history", "ao.history_written"),
                                options.aoSettings.temporalFrames, width, height);
        }
    } else {
        auto p =
            g.addPass("ambient_occlusion_reference", PassKind::Device,
                      [pass, depth, normal, raw, specular, aoInputs](PassContext& ctx) {
                          AmbientOcclusionPass::Inputs in = aoInputs;
                          in.depth = ctx.image(depth);
                          in.normalRoughMetal = ctx.image(normal);
                          pass->recordReference(ctx.cmd(), in, ctx.image(raw), ctx.image(specular));
                      });
        declareInputs(p);
        out.occlusion = p.write(raw, Use::StorageWrite);
        out.specular = p.write(specular, Use::StorageWrite);
    }
    frame.board.put(out);
}

void AmbientOcclusionFeature::restartHistory() {
    history_->invalidate();
    frame_ = 0;
}

void AmbientOcclusionFeature::collectStats(RendererStats& stats, bool) const {
    stats.aoMs = passMilliseconds(stats, "ambient_occlusion_");
}

}  // namespace candela::render
