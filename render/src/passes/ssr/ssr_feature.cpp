#include "passes/ssr/ssr_feature.h"

#include <string>

#include "candela/content/render_setting_table.h"
#include "candela/render/frame_inputs.h"
#include "features/gbuffer_frame.h"
#include "features/scene_targets.h"
#include "frame_graph/frame_graph_executor.h"
#include "lit_inputs.h"
#include "passes/ambient_occlusion/ambient_occlusion_frame.h"
#include "passes/lighting/lighting_pass.h"
#include "passes/ssr/ssr_pass.h"
#include "renderer_scene_queries.h"
#include "temporal_history.h"

namespace candela::render {

namespace {

// A mip chain written one level per pass (`name` + level), each after the level below it: the
// pass for level i reads the camera, what `reads(p, i)` adds and the image as the level before
// left it, and `record(ctx, image, i)` writes level i. Returns the image's last version.
template <class Reads, class Record>
ResourceHandle declareLevels(FrameGraph& g, const std::string& name, ResourceHandle image,
                             uint32_t levels, Reads reads, Record record, ResourceHandle camera) {
    for (uint32_t level = 0; level < levels; ++level) {
        const ResourceHandle source = image;
        auto p =
            g.addPass(name + std::to_string(level), PassKind::Device,
                      [record, source, level](PassContext& ctx) { record(ctx, source, level); });
        p.read(camera, Use::Uniform);
        reads(p, level);
        image = p.write(image, level == 0 ? Use::StorageWrite : Use::StorageReadWrite);
    }
    return image;
}

}  // namespace

SsrFeature::SsrFeature(GpuContext& context)
    : context_(context), history_(std::make_unique<TemporalHistory>()) {}

SsrFeature::~SsrFeature() = default;

bool SsrFeature::active(const FeatureFrame& frame) const {
    return frame.options.ssr != SsrMode::Off &&
           hasGlossySurface(frame.inputs.scene, frame.resources,
                            frame.options.ssrSettings.roughnessCutoff);
}

void SsrFeature::declare(FeatureFrame& frame) {
    FrameGraph& g = frame.graph;
    const RendererOptions& options = frame.options;
    const uint32_t width = frame.width;
    const uint32_t height = frame.height;
    SceneTargets& targets = frame.board.get<SceneTargets>();
    const GBufferFrame& gbuffer = frame.board.get<GBufferFrame>();
    const LitFrame& lit = frame.board.get<LitFrame>();
    const AmbientOcclusionFrame& ao = frame.board.get<AmbientOcclusionFrame>();
    frame.features.push_back("ssr_" + content::renderSettingName(options.ssr));
    if (!pass_) pass_ = std::make_unique<SsrPass>(context_);
    SsrPass* pass = pass_.get();
    const GpuBuffer* cameraBuffer = lit.inputs.camera;
    const ResourceHandle camera = targets.camera;
    const ResourceHandle depth = targets.depth;
    ResourceHandle counters = g.importBuffer("ssr.counters", &pass->counters(), true);
    {
        auto p = g.addPass("ssr_clear", PassKind::Device,
                           [pass](PassContext& ctx) { pass->recordClearCounters(ctx.cmd()); });
        counters = p.write(counters, Use::TransferDst);
    }
    // The pyramid: the depth's min/max chain.
    const uint32_t levels = SsrPass::levelCount(width, height);
    const ResourceHandle pyramid = declareLevels(
        g, "ssr_hiz", g.createImage("ssr.hiz", SsrPass::pyramidDesc(width, height)), levels,
        [depth](FrameGraph::PassBuilder& p, uint32_t) { p.read(depth, Use::Sampled); },
        [pass, cameraBuffer, depth, width, height](PassContext& ctx, ResourceHandle image,
                                                   uint32_t index) {
            pass->recordHiz(ctx.cmd(), *cameraBuffer, ctx.image(depth), ctx.image(image), index,
                            width, height);
        },
        camera);
    // The pre-integrated visibility: level 0 is 100%, each coarser level from the pyramid's
    // depth ranges and the level below it.
    const ResourceHandle visibility = declareLevels(
        g, "ssr_visibility",
        g.createImage("ssr.visibility", SsrPass::visibilityDesc(width, height)), levels,
        [pyramid](FrameGraph::PassBuilder& p, uint32_t) { p.read(pyramid, Use::StorageRead); },
        [pass, cameraBuffer, pyramid, width, height](PassContext& ctx, ResourceHandle image,
                                                     uint32_t index) {
            pass->recordVisibility(ctx.cmd(), *cameraBuffer, ctx.image(pyramid), ctx.image(image),
                                   index, width, height);
        },
        camera);
    // The pre-convolved scene: the lit HDR radiance and its blurred levels.
    ResourceHandle hdr = targets.hdr;
    const ResourceHandle colors = declareLevels(
        g, "ssr_color", g.createImage("ssr.colors", SsrPass::colorDesc(width, height)), levels,
        [hdr](FrameGraph::PassBuilder& p, uint32_t index) {
            if (index == 0) p.read(hdr, Use::StorageRead);
        },
        [pass, cameraBuffer, hdr, width, height](PassContext& ctx, ResourceHandle image,
                                                 uint32_t index) {
            pass->recordColor(ctx.cmd(), *cameraBuffer, ctx.image(hdr), ctx.image(image), index,
                              width, height);
        },
        camera);
    ResourceHandle reflection =
        g.createImage("ssr.reflection", SsrPass::reflectionDesc(width, height));
    SsrPass::TraceInputs in;
    in.camera = cameraBuffer;
    in.hasEnvironment = frame.lighting.ibl.has_value();
    in.hasLut = lit.brdfLut && frame.lighting.ibl != IblMode::Mobile;
    in.skyIntensity = lit.inputs.skyIntensity;
    in.aoMode = ao.mode;
    in.aoIntensity = ao.intensity;
    in.mode = options.ssr;
    in.settings = options.ssrSettings;
    in.width = width;
    in.height = height;
    const ResourceHandle normal = gbuffer.color[1], baseColor = gbuffer.color[0],
                         specular = gbuffer.color[2];
    {
        auto p =
            g.addPass("ssr_trace", PassKind::Device,
                      [pass, in, environment = lit.inputs.environment, normal, baseColor, specular,
                       pyramid, visibility, colors, reflection, ao = ao](PassContext& ctx) {
                          SsrPass::TraceInputs inputs = in;
                          inputs.environment = &environment;
                          inputs.normalRoughMetal = ctx.image(normal);
                          inputs.baseColor = ctx.image(baseColor);
                          inputs.specularModel = ctx.image(specular);
                          inputs.pyramid = ctx.image(pyramid);
                          inputs.visibility = ctx.image(visibility);
                          if (ao.occlusion) inputs.ambientOcclusion = ctx.image(*ao.occlusion);
                          if (ao.specular) inputs.specularOcclusion = ctx.image(*ao.specular);
                          inputs.colors = ctx.image(colors);
                          pass->recordTrace(ctx.cmd(), inputs, ctx.image(reflection));
                      });
        p.read(camera, Use::Uniform);
        p.read(normal, Use::Sampled);
        p.read(baseColor, Use::Sampled);
        p.read(specular, Use::Sampled);
        p.read(pyramid, Use::StorageRead);
        p.read(visibility, Use::StorageRead);
        p.read(colors, Use::StorageRead);
        if (ao.occlusion) p.read(*ao.occlusion, Use::Sampled);
        if (ao.specular) p.read(*ao.specular, Use::Sampled);
        p.write(counters, Use::StorageReadWrite);
        reflection = p.write(reflection, Use::StorageWrite);
    }
    if (options.ssrSettings.temporal) {
        frame.features.push_back("ssr_temporal");
        history_->ensure(context_, SsrPass::historyDesc(width, height), 16);
        const TemporalHistory::Frame frameHistory =
            history_->declare(g, "ssr.history", "ssr.history_written");
        const ResourceHandle history = frameHistory.previous;
        ResourceHandle filtered = frameHistory.written;
        const ResourceHandle motion = targets.motion;
        const ResourceHandle current = reflection;
        const bool valid = frameHistory.valid;
        const float blend = options.ssrSettings.temporalBlend;
        auto t = g.addPass("ssr_temporal", PassKind::Device,
                           [pass, cameraBuffer, current, motion, history, filtered, valid,
                            blend](PassContext& ctx) {
                               pass->recordTemporal(ctx.cmd(), *cameraBuffer, ctx.image(current),
                                                    ctx.image(motion), ctx.image(history), valid,
                                                    blend, ctx.image(filtered));
                           });
        t.read(camera, Use::Uniform);
        t.read(current, Use::Sampled);
        t.read(motion, Use::Sampled);
        t.read(history, Use::Sampled);
        reflection = t.write(filtered, Use::StorageWrite);
    }
    auto p = g.addPass(
        "ssr_composite", PassKind::Device, [pass, cameraBuffer, reflection, hdr](PassContext& ctx) {
            pass->recordComposite(ctx.cmd(), *cameraBuffer, ctx.image(reflection), ctx.image(hdr));
        });
    p.read(camera, Use::Uniform);
    p.read(reflection, Use::Sampled);
    hdr = p.write(hdr, Use::StorageReadWrite);
    targets.hdr = hdr;
}

void SsrFeature::collectStats(RendererStats& stats, bool declared) const {
    stats.ssrMs = passMilliseconds(stats, "ssr_");
    stats.ssrStepsMean = 0.0;
    stats.ssrStepsMax = 0;
    stats.ssrHitRate = 0.0;
    stats.ssrRays = 0;
    stats.work.ssrSteps = 0;
    if (!declared) return;
    const SsrPass::Counts c = pass_->readCounters();
    stats.work.ssrSteps = c.steps;
    stats.ssrRays = c.rays;
    stats.ssrStepsMax = c.maxSteps;
    if (c.rays > 0) {
        stats.ssrStepsMean = double(c.steps) / c.rays;
        stats.ssrHitRate = double(c.hits) / c.rays;
    }
}

void SsrFeature::restartHistory() {
    history_->invalidate();
}

}  // namespace candela::render
