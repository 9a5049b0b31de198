// Screen-space reflections' frame-graph declaration (Renderer::declareSsr): the Hi-Z pyramid,
// its pre-integrated visibility, the pre-convolved scene colours, the trace, the optional
// temporal filter and the composite into the HDR target.

#include <string>

#include "candela/render/renderer.h"
#include "frame_graph/frame_graph.h"
#include "frame_graph/frame_graph_executor.h"
#include "ibl/environment_brdf_lut.h"
#include "ibl/environment_descriptors.h"
#include "passes/ssr/ssr_pass.h"
#include "renderer_frame_handles.h"
#include "temporal_history.h"

namespace candela::render {

uint32_t Renderer::declareSsr(const SceneHandles& h, const EnvironmentDescriptors& environment,
                              bool sky, bool mobileIbl, float skyIntensity,
                              const SsrOcclusion& ao) {
    FrameGraph& g = *graph_;
    features_.push_back(std::string("ssr_") + ssrModeName(options_.ssr));
    if (!ssrPass_) ssrPass_ = std::make_unique<SsrPass>(context_);
    ssrTraced_ = true;
    const ResourceHandle camera = h.camera;
    const ResourceHandle depth = h.depth;
    ResourceHandle counters = g.importBuffer("ssr.counters", &ssrPass_->counters(), true);
    {
        auto p = g.addPass("ssr_clear", PassKind::Device,
                           [this](PassContext& ctx) { ssrPass_->recordClearCounters(ctx.cmd()); });
        counters = p.write(counters, Use::TransferDst);
    }
    // The pyramid: one pass per level (each reads the level below, which the graph orders).
    ResourceHandle pyramid = g.createImage("ssr.hiz", SsrPass::pyramidDesc(width_, height_));
    const uint32_t levels = SsrPass::levelCount(width_, height_);
    for (uint32_t level = 0; level < levels; ++level) {
        const ResourceHandle source = pyramid;
        auto p = g.addPass("ssr_hiz" + std::to_string(level), PassKind::Device,
                           [this, depth, source, level](PassContext& ctx) {
                               ssrPass_->recordHiz(ctx.cmd(), cameraBuffer_, ctx.image(depth),
                                                   ctx.image(source), level, width_, height_);
                           });
        p.read(camera, Use::Uniform);
        p.read(depth, Use::Sampled);
        pyramid = p.write(pyramid, level == 0 ? Use::StorageWrite : Use::StorageReadWrite);
    }
    // The pre-integrated visibility: level 0 is 100%, each coarser level from the pyramid's
    // depth ranges and the level below it.
    ResourceHandle visibility =
        g.createImage("ssr.visibility", SsrPass::visibilityDesc(width_, height_));
    for (uint32_t level = 0; level < levels; ++level) {
        const ResourceHandle source = pyramid, target = visibility;
        auto p =
            g.addPass("ssr_visibility" + std::to_string(level), PassKind::Device,
                      [this, source, target, level](PassContext& ctx) {
                          ssrPass_->recordVisibility(ctx.cmd(), cameraBuffer_, ctx.image(source),
                                                     ctx.image(target), level, width_, height_);
                      });
        p.read(camera, Use::Uniform);
        p.read(pyramid, Use::StorageRead);
        visibility = p.write(visibility, level == 0 ? Use::StorageWrite : Use::StorageReadWrite);
    }
    // The pre-convolved scene: the lit HDR radiance and its blurred levels.
    ResourceHandle hdr = h.hdr;
    ResourceHandle colors = g.createImage("ssr.colors", SsrPass::colorDesc(width_, height_));
    for (uint32_t level = 0; level < levels; ++level) {
        const ResourceHandle source = colors;
        auto p = g.addPass("ssr_color" + std::to_string(level), PassKind::Device,
                           [this, hdr, source, level](PassContext& ctx) {
                               ssrPass_->recordColor(ctx.cmd(), cameraBuffer_, ctx.image(hdr),
                                                     ctx.image(source), level, width_, height_);
                           });
        p.read(camera, Use::Uniform);
        if (level == 0) p.read(hdr, Use::StorageRead);
        colors = p.write(colors, level == 0 ? Use::StorageWrite : Use::StorageReadWrite);
    }
    ResourceHandle reflection =
        g.createImage("ssr.reflection", SsrPass::reflectionDesc(width_, height_));
    SsrPass::TraceInputs in;
    in.camera = &cameraBuffer_;
    in.hasEnvironment = sky;
    in.hasLut = brdfLut_ != nullptr && !mobileIbl;
    in.skyIntensity = skyIntensity;
    in.aoMode = ao.mode;
    in.aoIntensity = ao.intensity;
    in.mode = options_.ssr;
    in.settings = options_.ssrSettings;
    in.width = width_;
    in.height = height_;
    const ResourceHandle normal = h.color[1], baseColor = h.color[0], specular = h.color[2];
    {
        auto p = g.addPass("ssr_trace", PassKind::Device,
                           [this, in, environment, normal, baseColor, specular, pyramid, visibility,
                            colors, reflection, ao = ao](PassContext& ctx) {
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
                               ssrPass_->recordTrace(ctx.cmd(), inputs, ctx.image(reflection));
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
    if (options_.ssrSettings.temporal) {
        features_.push_back("ssr_temporal");
        const TemporalHistory::Frame frame =
            ssrHistory_->declare(g, "ssr.history", "ssr.history_written");
        const ResourceHandle history = frame.previous;
        ResourceHandle filtered = frame.written;
        const ResourceHandle motion = h.motion;
        const ResourceHandle current = reflection;
        const bool valid = frame.valid;
        const float blend = options_.ssrSettings.temporalBlend;
        auto t =
            g.addPass("ssr_temporal", PassKind::Device,
                      [this, current, motion, history, filtered, valid, blend](PassContext& ctx) {
                          ssrPass_->recordTemporal(ctx.cmd(), cameraBuffer_, ctx.image(current),
                                                   ctx.image(motion), ctx.image(history), valid,
                                                   blend, ctx.image(filtered));
                      });
        t.read(camera, Use::Uniform);
        t.read(current, Use::Sampled);
        t.read(motion, Use::Sampled);
        t.read(history, Use::Sampled);
        reflection = t.write(filtered, Use::StorageWrite);
    }
    auto p =
        g.addPass("ssr_composite", PassKind::Device, [this, reflection, hdr](PassContext& ctx) {
            ssrPass_->recordComposite(ctx.cmd(), cameraBuffer_, ctx.image(reflection),
                                      ctx.image(hdr));
        });
    p.read(camera, Use::Uniform);
    p.read(reflection, Use::Sampled);
    hdr = p.write(hdr, Use::StorageReadWrite);
    return hdr.version;
}

}  // namespace candela::render
