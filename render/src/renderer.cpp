#include "candela/render/renderer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

#include "candela/render/environment.h"
#include "candela/render/frame_submitter.h"
#include "candela/render/gpu_context.h"
#include "candela/render/scene_resources.h"
#include "clustered/cluster_light_lists.h"
#include "cpu_clock.h"
#include "culling/draw_bounds.h"
#include "culling/draw_order.h"
#include "culling/draws_in_view.h"
#include "features/declared_frame.h"
#include "features/feature_list.h"
#include "features/frame_blackboard.h"
#include "features/frame_exposure.h"
#include "features/gbuffer_frame.h"
#include "features/render_feature.h"
#include "features/scene_targets.h"
#include "frame_camera.h"
#include "frame_graph/frame_graph.h"
#include "frame_graph/frame_graph_executor.h"
#include "gbuffer_targets.h"
#include "lit_inputs.h"
#include "lit_scene.h"
#include "passes/ambient_occlusion/ambient_occlusion_feature.h"
#include "passes/ambient_occlusion/ambient_occlusion_frame.h"
#include "passes/bloom/bloom_feature.h"
#include "passes/exposure/auto_exposure_feature.h"
#include "passes/exposure/exposure_bindings.h"
#include "passes/forward_transparent/forward_transparent_pass.h"
#include "passes/forward_transparent/msaa_samples.h"
#include "passes/gbaa/gbaa_feature.h"
#include "passes/gbuffer/gbuffer_pass.h"
#include "passes/hair/hair_feature.h"
#include "passes/lighting/lighting_pass.h"
#include "passes/nonfinite/nonfinite_guard.h"
#include "passes/output/output_stage.h"
#include "passes/scattering/scattering_feature.h"
#include "passes/skinning/skinning_feature.h"
#include "passes/ssr/ssr_feature.h"
#include "passes/taa/taa_feature.h"
#include "passes/triangle/triangle_pass.h"
#include "passes/volumetrics/integrated_froxels.h"
#include "passes/volumetrics/volumetrics_feature.h"
#include "passes/wires/wire_feature.h"
#include "renderer_scene_queries.h"
#include "shading_tables.h"
#include "vk/vk_check.h"

namespace candela::render {

float exposureFromEv100(float ev100) {
    // Below an EV100 of about -127 the scale overflows; the largest float keeps every pass
    // that multiplies by it (TAA's clipping, tonemapping) away from 0 * Inf.
    const float exposure = 1.0f / (1.2f * std::exp2(ev100));
    return std::isfinite(exposure) ? exposure : std::numeric_limits<float>::max();
}

namespace {

// hdr and ldr: discarded at the start of a frame (the previous frame's copies out of them
// are fenced), left ready to be copied from (capture, swapchain blit) at its end.
constexpr ImageState kDiscardAfterCopies{VK_IMAGE_LAYOUT_UNDEFINED,
                                         VK_PIPELINE_STAGE_2_TRANSFER_BIT, 0};
constexpr ImageState kReadyToCopy{VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                  VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT};

}  // namespace

// The handles of one frame's scene passes. Passes capture resource ids by value; the versions
// they read are declared through the builder.
struct SceneHandles {
    std::array<ResourceHandle, 4> color;
    ResourceHandle depth, motion, hdr, camera, lights;
    bool extended = false;  // the anisotropy and clear-coat targets (gbuffer_targets.h)
    ResourceHandle anisotropy, clearCoat;
    bool hasEdges = false;       // GBAA's edge target (--aa gbaa; gbuffer_targets.h)
    bool separateEdges = false;  // written by its own pass (GBufferPass::separateEdges)
    ResourceHandle edges;
};

namespace {

// The G-buffer's images as a pass that records sees them.
GBufferTargets gbufferTargetsOf(const SceneHandles& ids, PassContext& ctx) {
    GBufferTargets targets;
    for (size_t i = 0; i < targets.color.size(); ++i)
        targets.color[i] = ctx.image(ids.color[i]);
    targets.depth = ctx.image(ids.depth);
    targets.motion = ctx.image(ids.motion);
    targets.extended = ids.extended;
    if (ids.extended) {
        targets.anisotropy = ctx.image(ids.anisotropy);
        targets.clearCoat = ctx.image(ids.clearCoat);
    }
    targets.hasEdges = ids.hasEdges && !ids.separateEdges;
    if (ids.hasEdges) targets.edges = ctx.image(ids.edges);
    return targets;
}

}  // namespace

Renderer::Renderer(GpuContext& context, uint32_t width, uint32_t height,
                   const RendererOptions& options)
    : context_(context),
      options_(options),
      graph_(std::make_unique<FrameGraph>()),
      executor_(std::make_unique<FrameGraphExecutor>(context)),
      lit_(std::make_unique<LitScene>(context, options_)),
      gbufferPass_(std::make_unique<GBufferPass>(context)),
      lightingPass_(std::make_unique<LightingPass>(context)),
      transparentPass_(std::make_unique<ForwardTransparentPass>(
          context, forwardMsaaSamples(context, options.msaaSamples))),
      features_(std::make_unique<FeatureList>()),
      output_(std::make_unique<OutputStage>(context, options_)),
      trianglePass_(std::make_unique<TrianglePass>(context)),
      nonFinite_(std::make_unique<NonFiniteGuard>(context)),
      frame_(std::make_unique<DeclaredFrame>()) {
    resize(width, height);
    // The features, in frame order within each run.
    FeatureList& f = *features_;
    f.add(FeatureRun::BeforeGeometry, std::make_unique<SkinningFeature>(context_));
    f.add(FeatureRun::BeforeLighting, std::make_unique<AmbientOcclusionFeature>(context_));
    f.add(FeatureRun::OverLitFrame, std::make_unique<SsrFeature>(context_));
    f.add(FeatureRun::OverLitFrame, std::make_unique<VolumetricsFeature>(context_));
    f.add(FeatureRun::OverLitFrame, std::make_unique<ScatteringFeature>(context_));
    f.add(FeatureRun::OverLitFrame, std::make_unique<HairFeature>(context_));
    f.add(FeatureRun::OverLitFrame, std::make_unique<WireFeature>(context_));
    f.add(FeatureRun::AfterScene, std::make_unique<TaaFeature>(context_));
    f.add(FeatureRun::AfterScene, std::make_unique<GbaaFeature>(context_));
    f.add(FeatureRun::AfterScene, std::make_unique<AutoExposureFeature>(context_));
    f.add(FeatureRun::AfterScene, std::make_unique<BloomFeature>(context_));
}

void Renderer::diagnoseNonFiniteNextFrame() {
    nonFinite_->diagnoseNextFrame();
}

const EnvironmentBrdfLut* Renderer::environmentBrdfLut() const {
    return lit_->tables().brdfLut();
}

const GpuImage& Renderer::hdrTarget() const {
    return output_->upscales() ? targets_.outputHdr : targets_.hdr;
}

std::vector<std::string> Renderer::features() const {
    return frame_->features;
}

uint32_t Renderer::scaledSize(uint32_t outputSize, float scale) {
    // Anything but a fraction in (0, 1] renders at the output size.
    if (!(scale > 0.0f && scale < 1.0f)) return outputSize;
    return std::max(1u, uint32_t(std::lround(double(outputSize) * scale)));
}

Renderer::~Renderer() = default;

LightAssignmentDevice Renderer::resolveLightAssignment(const RendererOptions& options,
                                                       const GpuContext& context) {
    if (options.lightAssignment != LightAssignmentDevice::Auto) return options.lightAssignment;
    // On a CPU device the "GPU" is the same cores: the job system's sort beats four compute
    // dispatches there (render/README.md, "CPU or compute assignment").
    return context.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU
               ? LightAssignmentDevice::Cpu
               : LightAssignmentDevice::Gpu;
}

uint32_t Renderer::declareScene(const FrameInputs& inputs, SceneResources& resources,
                                uint32_t hdrId) {
    DeclaredFrame& declared = *frame_;
    declared.work = {};
    FrameGraph& g = *graph_;
    const uint32_t width = targets_.width, height = targets_.height;
    // Every draw's world box, once: the shadow views' and the camera's culling read it.
    const std::vector<WorldBounds> drawBounds = worldBoundsOf(inputs.scene, resources);
    const LightingFeatures features =
        lit_->prepare(g, inputs, resources, drawBounds, width, height, stats_);
    lightingPass_->setFeatures(features);
    declared.features = features.names();
    // Layers blend in the G-buffer pass only; the lighting variant does not change with them.
    const std::vector<uint8_t> visible = visibleDraws(inputs, resources, drawBounds);
    gbufferPass_->prepare(inputs.scene, resources, visible,
                          usesMaterialLayers(inputs.scene, resources),
                          features.materialExtensions(), options_.aa == AntiAliasing::Gbaa,
                          nearestFirst(visible, drawBounds, inputs.scene.camera.position));
    if (gbufferPass_->materialLayers()) declared.features.push_back("material_layers");
    lit_->upload(inputs, features, width, height);
    // Blended draws leave the G-buffer for the forward pass; none, and it records nothing.
    const bool blended = transparentPass_->prepare(inputs.scene, resources, visible, features,
                                                   lit_->camera().previousWorlds());
    lit_->collectFrameStats(stats_, declared.work);

    SceneHandles h = createGBufferTargets(g, features.materialExtensions(), hdrId);
    const LitScene::Buffers buffers = lit_->importBuffers(g);
    h.camera = buffers.camera;
    h.lights = buffers.lights;
    ResourceHandle pairCounts =
        g.importBuffer("lighting.pair_counts", &targets_.pairCounts, features.countLightPairs);
    if (features.countLightPairs) {  // the lighting pass adds its counts atomically
        auto p = g.addPass("lighting_counts_clear", PassKind::Device, [this](PassContext& ctx) {
            vkCmdFillBuffer(ctx.cmd(), targets_.pairCounts.handle(), 0, VK_WHOLE_SIZE, 0);
        });
        pairCounts = p.write(pairCounts, Use::TransferDst);
    }
    // The features get what the frame so far gives them (the blackboard, filled as it goes).
    FrameBlackboard& board = declared.board;
    board.clear();
    FeatureFrame frame{g,      inputs,   resources, options_,          width,
                       height, features, board,     declared.features, declared.work};
    stats_.deformedDraws = uint32_t(inputs.scene.deforms.size());
    features_->declareRun(frame, FeatureRun::BeforeGeometry);
    const DeformedVertices* deformedVertices = board.find<DeformedVertices>();
    const ResourceHandle deformed = deformedVertices ? deformedVertices->buffers : ResourceHandle{};
    const LitScene::Maps maps = lit_->declareMaps(g, inputs, resources, features, deformed, stats_);
    declareGBuffer(h, inputs, resources, deformed);
    lit_->declareClusters(g, inputs, resources, features, buffers, maps, h.depth,
                          blended ? transparentPass_.get() : nullptr, deformed, board, stats_);
    // Ambient occlusion between the G-buffer and lighting; then SSR, volumetrics, light shafts,
    // hair and wires over the lit frame and its medium, under the blended surfaces (which then
    // see the hair's depth); then the post features on the HDR target (recordFrame).
    SceneTargets& targets = board.put(SceneTargets{h.hdr, h.depth, h.motion, h.camera});
    board.put(GBufferFrame{h.color, h.hasEdges ? std::optional(h.edges) : std::nullopt});
    features_->declareRun(frame, FeatureRun::BeforeLighting);
    declareLighting(h, inputs, pairCounts);
    h.hdr = lit_->declareSky(g, inputs, h.camera, h.depth, h.hdr, declared.features);
    targets.hdr = h.hdr;
    board.put(declareIntegratedFroxels(g, inputs.scene, options_, width, height, blended));
    features_->declareRun(frame, FeatureRun::OverLitFrame);
    h.hdr = targets.hdr;
    h.depth = targets.depth;
    if (blended) declareTransparency(h, resources, deformed);
    targets.hdr = h.hdr;
    targets.motion = h.motion;
    return h.hdr.version;
}

std::vector<uint8_t> Renderer::visibleDraws(const FrameInputs& inputs,
                                            const SceneResources& resources,
                                            std::span<const WorldBounds> drawBounds) {
    // The draws the camera sees, each at its level of detail: the G-buffer and forward passes
    // record no other. The sides widen by two pixels for TAA's jitter, which moves the image
    // after this test. --culling off: a frustum that holds everything.
    const CameraView& view = inputs.scene.camera;
    const float width = float(targets_.width), height = float(targets_.height);
    const ViewFrustum frustum =
        options_.culling ? viewFrustumOf(view.projection * view.view, {4.0f / width, 4.0f / height})
                         : ViewFrustum{};
    std::vector<uint8_t> visible = drawsInView(
        inputs.scene, resources, drawBounds, frustum,
        perspectiveLodView(view.position, view.projection, height, options_.lodPixelError));
    stats_.draws = uint32_t(visible.size());
    stats_.drawsCulled = uint32_t(std::count(visible.begin(), visible.end(), kDrawCulled));
    for (size_t i = 0; i < visible.size(); ++i) {
        if (visible[i] != kDrawCulled)
            frame_->work.triangles +=
                resources.mesh(inputs.scene.draws[i].mesh).lods[visible[i]].indexCount / 3;
    }
    return visible;
}

SceneHandles Renderer::createGBufferTargets(FrameGraph& g, bool extended, uint32_t hdr) {
    const uint32_t width = targets_.width, height = targets_.height;
    SceneHandles h;
    h.hdr = {hdr, 0};
    for (size_t i = 0; i < h.color.size(); ++i) {
        h.color[i] = g.createImage(GBufferTargets::kColorNames[i],
                                   GBufferTargets::colorDesc(i, width, height));
    }
    h.depth = g.createImage("gbuffer.depth", GBufferTargets::depthDesc(width, height));
    h.motion =
        g.createImage(GBufferTargets::kMotionName, GBufferTargets::motionDesc(width, height));
    h.extended = extended;
    if (h.extended) {
        h.anisotropy = g.createImage(
            "gbuffer.anisotropy",
            GBufferTargets::extensionDesc(GBufferTargets::kAnisotropyFormat, width, height));
        h.clearCoat = g.createImage(
            "gbuffer.clear_coat",
            GBufferTargets::extensionDesc(GBufferTargets::kClearCoatFormat, width, height));
    }
    h.hasEdges = options_.aa == AntiAliasing::Gbaa;
    h.separateEdges = GBufferPass::separateEdges(h.extended, h.hasEdges);
    if (h.hasEdges) {
        h.edges = g.createImage(
            GBufferTargets::kEdgesName,
            GBufferTargets::extensionDesc(GBufferTargets::kEdgesFormat, width, height));
    }
    return h;
}

void Renderer::declareGBuffer(SceneHandles& h, const FrameInputs& inputs, SceneResources& resources,
                              ResourceHandle deformed) {
    FrameGraph& g = *graph_;
    const SceneHandles ids = h;  // resource ids for the passes to look up
    const GpuBuffer& camera = lit_->camera().buffer();
    const auto& previousWorlds = lit_->camera().previousWorlds();
    {
        auto p =
            g.addPass("gbuffer", PassKind::Device,
                      [this, ids, &inputs, &resources, &camera, &previousWorlds](PassContext& ctx) {
                          gbufferPass_->record(ctx.cmd(), gbufferTargetsOf(ids, ctx),
                                               ctx.image(ids.hdr), inputs.clearRadiance,
                                               inputs.scene, resources, camera, previousWorlds);
                      });
        // GBAA's geometry stage reads the target size from the camera block too.
        p.read(h.camera, Use::Uniform,
               kRasterStages | (h.hasEdges ? VK_PIPELINE_STAGE_2_GEOMETRY_SHADER_BIT
                                           : VkPipelineStageFlags2(0)));
        if (deformed.valid()) p.read(deformed, Use::VertexInput);
        for (ResourceHandle& c : h.color)
            c = p.write(c, Use::ColorAttachment);
        h.motion = p.write(h.motion, Use::ColorAttachment);
        h.depth = p.write(h.depth, Use::DepthWrite);
        h.hdr = p.write(h.hdr, Use::ColorAttachment);
        if (h.extended) {
            h.anisotropy = p.write(h.anisotropy, Use::ColorAttachment);
            h.clearCoat = p.write(h.clearCoat, Use::ColorAttachment);
        }
        if (h.hasEdges && !h.separateEdges) h.edges = p.write(h.edges, Use::ColorAttachment);
    }
    if (h.separateEdges) {
        auto p = g.addPass(
            "gbuffer_edges", PassKind::Device,
            [this, ids, &inputs, &resources, &camera, &previousWorlds](PassContext& ctx) {
                gbufferPass_->recordEdges(ctx.cmd(), ctx.image(ids.edges), ctx.image(ids.depth),
                                          inputs.scene, resources, camera, previousWorlds);
            });
        p.read(h.camera, Use::Uniform, kRasterStages | VK_PIPELINE_STAGE_2_GEOMETRY_SHADER_BIT);
        if (deformed.valid()) p.read(deformed, Use::VertexInput);
        p.read(h.depth, Use::DepthRead);
        h.edges = p.write(h.edges, Use::ColorAttachment);
    }
}

void Renderer::declareLighting(SceneHandles& h, const FrameInputs& inputs,
                               ResourceHandle pairCounts) {
    FrameBlackboard& board = frame_->board;
    const LitFrame& litFrame = board.get<LitFrame>();
    const LitInputs lit = litFrame.inputs;
    const float aoIntensity = std::clamp(inputs.scene.aoIntensity, 0.0f, 1.0f);
    if (!board.find<AmbientOcclusionFrame>())
        board.put(AmbientOcclusionFrame{{}, {}, 0, aoIntensity});
    const std::optional<ResourceHandle> occlusion = board.get<AmbientOcclusionFrame>().occlusion;
    const std::optional<ResourceHandle> specularOcclusion =
        board.get<AmbientOcclusionFrame>().specular;
    const bool aoMultiBounce = options_.aoSettings.multiBounce;
    const bool countLightPairs = lightingPass_->features().countLightPairs;
    const uint32_t lightCount = litFrame.lightCount;
    const SceneHandles ids = h;
    auto p = graph_->addPass(
        "lighting", PassKind::Device,
        [this, ids, lit, lightCount, occlusion, specularOcclusion, aoIntensity,
         aoMultiBounce](PassContext& ctx) {
            const GBufferTargets gbuffer = gbufferTargetsOf(ids, ctx);
            LightingPass::Inputs lighting{&gbuffer, ctx.image(ids.hdr), lit, &targets_.pairCounts};
            lighting.lightCount = lightCount;
            lighting.referenceSamples = options_.referenceSamples;
            if (occlusion) lighting.ambientOcclusion = ctx.image(*occlusion);
            if (specularOcclusion) lighting.specularOcclusion = ctx.image(*specularOcclusion);
            lighting.aoIntensity = aoIntensity;
            lighting.aoMultiBounce = aoMultiBounce;
            lightingPass_->record(ctx.cmd(), lighting);
        });
    for (ResourceHandle c : h.color)
        p.read(c, Use::Sampled);
    p.read(h.depth, Use::Sampled);
    if (h.extended) {
        p.read(h.anisotropy, Use::Sampled);
        p.read(h.clearCoat, Use::Sampled);
    }
    p.read(h.camera, Use::Uniform);
    litFrame.reads.declareReads(p, kComputeStage);
    if (occlusion) p.read(*occlusion, Use::Sampled);
    if (specularOcclusion) p.read(*specularOcclusion, Use::Sampled);
    if (countLightPairs) p.write(pairCounts, Use::StorageReadWrite);  // atomics
    h.hdr = p.write(h.hdr, Use::StorageReadWrite);
}

void Renderer::declareTransparency(SceneHandles& h, SceneResources& resources,
                                   ResourceHandle deformed) {
    FrameGraph& g = *graph_;
    const FrameBlackboard& board = frame_->board;
    const LitFrame& litFrame = board.get<LitFrame>();
    const LitInputs lit = litFrame.inputs;
    const std::optional<ResourceHandle> froxels = board.get<IntegratedFroxels>().buffer;
    const uint32_t width = targets_.width, height = targets_.height;
    // MSAA: multisampled copies of the targets, made only for frames with blended draws.
    const VkSampleCountFlagBits samples = transparentPass_->samples();
    const bool msaa = samples != VK_SAMPLE_COUNT_1_BIT;
    ResourceHandle msaaHdr, msaaMotion, msaaDepth;
    if (msaa) {
        msaaHdr = g.createImage("forward.msaa_hdr",
                                ForwardTransparentPass::msaaHdrDesc(width, height, samples));
        msaaMotion = g.createImage("forward.msaa_motion",
                                   ForwardTransparentPass::msaaMotionDesc(width, height, samples));
        msaaDepth = g.createImage("forward.msaa_depth",
                                  ForwardTransparentPass::msaaDepthDesc(width, height, samples));
    }
    const SceneHandles ids = h;
    auto shadingInputs = [ids, lit, msaa, msaaHdr, msaaMotion, msaaDepth](PassContext& ctx) {
        ForwardTransparentPass::ShadingInputs in{};
        in.hdr = ctx.image(ids.hdr);
        in.motion = ctx.image(ids.motion);
        in.depth = ctx.image(ids.depth);
        in.lit = lit;
        if (msaa) {
            in.msaaHdr = ctx.image(msaaHdr);
            in.msaaMotion = ctx.image(msaaMotion);
            in.msaaDepth = ctx.image(msaaDepth);
        }
        return in;
    };
    if (msaa) {
        frame_->features.push_back("forward_msaa");
        auto e = g.addPass("forward_msaa_expand", PassKind::Device,
                           [this, shadingInputs](PassContext& ctx) {
                               transparentPass_->recordExpand(ctx.cmd(), shadingInputs(ctx));
                           });
        e.read(h.hdr, Use::Sampled, kFragmentStage);
        e.read(h.motion, Use::Sampled, kFragmentStage);
        e.read(h.depth, Use::Sampled, kFragmentStage);
        msaaHdr = e.write(msaaHdr, Use::ColorAttachment);
        msaaMotion = e.write(msaaMotion, Use::ColorAttachment);
        msaaDepth = e.write(msaaDepth, Use::DepthWrite);
    }
    auto p = g.addPass("forward_transparent", PassKind::Device,
                       [this, shadingInputs, froxels, &resources](PassContext& ctx) {
                           ForwardTransparentPass::ShadingInputs in = shadingInputs(ctx);
                           if (froxels) {
                               in.froxels = true;
                               in.froxelIntegrated = ctx.buffer(*froxels);
                           }
                           transparentPass_->recordShading(ctx.cmd(), resources, in);
                       });
    if (froxels) p.read(*froxels, Use::StorageRead, kFragmentStage);
    if (msaa) {
        // Drawn into, then resolved into hdr and motion (their last use).
        p.read(msaaDepth, Use::DepthRead);
        p.write(msaaHdr, Use::ColorAttachment);
        p.write(msaaMotion, Use::ColorAttachment);
    } else {
        p.read(h.depth, Use::DepthRead);
    }
    p.read(h.camera, Use::Uniform, kRasterStages);
    if (deformed.valid()) p.read(deformed, Use::VertexInput);
    litFrame.reads.declareReads(p, kFragmentStage);
    h.hdr = p.write(h.hdr, Use::ColorAttachment);
    h.motion = p.write(h.motion, Use::ColorAttachment);
    frame_->features.push_back("forward_transparency");
}

namespace {

Use graphUse(TargetUse use) {
    switch (use) {
        case TargetUse::StorageRead:
            return Use::StorageRead;
        case TargetUse::StorageWrite:
            return Use::StorageWrite;
        case TargetUse::StorageReadWrite:
            return Use::StorageReadWrite;
        case TargetUse::ColorAttachment:
            return Use::ColorAttachment;
        case TargetUse::TransferSrc:
            return Use::TransferSrc;
    }
    return Use::StorageRead;
}

// Storage uses happen in compute shaders; the other uses ignore the stages.
VkPipelineStageFlags2 graphStages(TargetUse) {
    return kComputeStage;
}

}  // namespace

VkImageLayout Renderer::targetLayout(TargetUse use) {
    return useInfo(graphUse(use), graphStages(use)).layout;
}

VkCommandBuffer Renderer::recordFrame(FrameSubmitter& submitter, const FrameInputs& inputs,
                                      SceneResources* resources,
                                      std::span<const ExtraPass> extraPasses) {
    VkCommandBuffer cmd = submitter.begin();
    const CpuClock::time_point start = CpuClock::now();
    FrameGraph& g = *graph_;
    DeclaredFrame& declared = *frame_;
    g.clear();
    ResourceHandle hdr = g.importImage("hdr", &targets_.hdr, kDiscardAfterCopies, kReadyToCopy);
    ResourceHandle ldr = g.importImage("ldr", &targets_.ldr, kDiscardAfterCopies, kReadyToCopy);
    const bool sceneFrame = !inputs.testTriangleRadiance && resources;
    if (!sceneFrame) {
        const std::array<float, 4> clear = inputs.clearRadiance;
        const std::array<float, 4> radiance = inputs.testTriangleRadiance.value_or(clear);
        auto p =
            g.addPass("triangle", PassKind::Device, [this, hdr, clear, radiance](PassContext& ctx) {
                trianglePass_->record(ctx.cmd(), ctx.image(hdr), clear, radiance);
            });
        hdr = p.write(hdr, Use::ColorAttachment);
        declared.features = {"test_triangle"};
        features_->sitOut();  // a frame without the scene breaks every sequence
    } else {
        hdr.version = declareScene(inputs, *resources, hdr.id);
        if (options_.captureMotionVectors)
            declareMotionCapture(declared.board.get<SceneTargets>().motion);
    }
    // Auto exposure reads the histogram of the previous frame, which begin() waited for.
    float ev100 = inputs.scene.camera.ev100;
    stats_.exposureEv100 = ev100;
    stats_.adaptedEv100 = ev100;
    if (options_.exposure == ExposureMode::Auto && sceneFrame) {
        AutoExposureSettings exposureSettings = options_.autoExposure;
        exposureSettings.compensation = options_.exposureCompensation;
        ev100 = features_->find<AutoExposureFeature>()->ev100(inputs, exposureSettings, stats_);
    }
    const float exposure = exposureFromEv100(ev100);
    if (sceneFrame) {
        // The post features (TAA, GBAA, the exposure histogram, bloom) on the scene's HDR
        // target, as the scene's passes left it.
        SceneTargets& targets = declared.board.get<SceneTargets>();
        targets.hdr = hdr;
        declared.board.put(FrameExposure{exposure});
        FeatureFrame frame{g,
                           inputs,
                           *resources,
                           options_,
                           targets_.width,
                           targets_.height,
                           lightingPass_->features(),
                           declared.board,
                           declared.features,
                           declared.work};
        features_->declareRun(frame, FeatureRun::AfterScene);
        hdr = targets.hdr;
    }
    if (output_->upscales()) {
        const ResourceHandle outputHdr =
            g.importImage("hdr.output", &targets_.outputHdr, kDiscardAfterCopies, kReadyToCopy);
        hdr = output_->declareUpscale(g, hdr, outputHdr, declared.features);
    }
    if (nonFinite_->checks(options_.checkNonFinite)) {
        nonFinite_->declareCheck(g, hdr);
    } else {
        nonFinite_->skipCheck();
    }
    ldr = output_->declareDisplay(g, hdr, ldr, exposure, inputs.text, targets_.outputWidth,
                                  targets_.outputHeight, declared.features);
    for (const ExtraPass& extra : extraPasses) {
        auto p = g.addPass(extra.name, PassKind::Device,
                           [record = extra.record](PassContext& ctx) { record(ctx.cmd()); });
        p.sideEffect();  // asked for by the caller: kept even when it only reads
        for (const TargetAccess& access : extra.uses) {
            ResourceHandle& target = access.target == FrameTarget::Hdr ? hdr : ldr;
            const Use use = graphUse(access.use);
            if (useInfo(use, graphStages(access.use)).writes) {
                target = p.write(target, use, graphStages(access.use));
            } else {
                p.read(target, use, graphStages(access.use));
            }
        }
    }
    if (nonFinite_->declareProbes(g)) declared.features.push_back("nonfinite_probes");
    const double recordMs = millisecondsSince(start);
    executor_->execute(g, submitter, cmd);
    declared.recorded = sceneFrame ? RecordedFrame::Scene : RecordedFrame::TestTriangle;
    stats_.frameGraph = executor_->stats();
    stats_.frameGraph.recordMs = recordMs;
    const GpuContext::PipelineStatistics pipelines = context_.pipelineStatistics();
    stats_.pipelinesCreated = pipelines.created;
    stats_.pipelineCreateMs = pipelines.createMs;
    return cmd;
}

std::string Renderer::frameGraphDot() const {
    return executor_->dot(*graph_);
}

}  // namespace candela::render
