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
#include "culling/draw_order.h"
#include "culling/draws_in_view.h"
#include "features/frame_blackboard.h"
#include "features/frame_exposure.h"
#include "features/gbuffer_frame.h"
#include "features/render_feature.h"
#include "features/scene_targets.h"
#include "frame_camera.h"
#include "frame_graph/frame_graph.h"
#include "frame_graph/frame_graph_executor.h"
#include "gbuffer_targets.h"
#include "gpu_camera.h"
#include "ibl/environment_descriptors.h"
#include "lights/gpu_light_buffer.h"
#include "lights/gpu_light_types.h"
#include "lit_inputs.h"
#include "passes/ambient_occlusion/ambient_occlusion_feature.h"
#include "passes/ambient_occlusion/ambient_occlusion_frame.h"
#include "passes/atmosphere/atmosphere_pass.h"
#include "passes/bloom/bloom_feature.h"
#include "passes/debug_text/debug_text_pass.h"
#include "passes/exposure/auto_exposure_feature.h"
#include "passes/exposure/exposure_bindings.h"
#include "passes/forward_transparent/forward_transparent_pass.h"
#include "passes/forward_transparent/msaa_samples.h"
#include "passes/fxaa/fxaa_pass.h"
#include "passes/gbaa/gbaa_feature.h"
#include "passes/gbuffer/gbuffer_pass.h"
#include "passes/hair/hair_feature.h"
#include "passes/lighting/lighting_pass.h"
#include "passes/nonfinite/nonfinite_guard.h"
#include "passes/scattering/scattering_feature.h"
#include "passes/shadows/shadow_frame.h"
#include "passes/shadows/shadow_pass.h"
#include "passes/skinning/skinning_feature.h"
#include "passes/sky_occlusion/sky_occlusion_pass.h"
#include "passes/ssr/ssr_feature.h"
#include "passes/taa/taa_feature.h"
#include "passes/tonemap/tonemap_pass.h"
#include "passes/triangle/triangle_pass.h"
#include "passes/upscale/upscale_pass.h"
#include "passes/volumetrics/integrated_froxels.h"
#include "passes/volumetrics/volumetrics_feature.h"
#include "passes/wires/wire_feature.h"
#include "renderer_frame_handles.h"
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

Renderer::Renderer(GpuContext& context, uint32_t width, uint32_t height,
                   const RendererOptions& options)
    : context_(context),
      options_(options),
      outputWidth_(width),
      outputHeight_(height),
      width_(scaledSize(width, options.renderScale)),
      height_(scaledSize(height, options.renderScale)),
      lightAssignment_(resolveLightAssignment(options, context)),
      graph_(std::make_unique<FrameGraph>()),
      executor_(std::make_unique<FrameGraphExecutor>(context)),
      camera_(std::make_unique<FrameCamera>(context)),
      lights_(std::make_unique<GpuLightBuffer>()),
      clusters_(std::make_unique<ClusterLightLists>(context, options_, lightAssignment_)),
      board_(std::make_unique<FrameBlackboard>()) {
    createTargets();
    trianglePass_ = std::make_unique<TrianglePass>(context_);
    gbufferPass_ = std::make_unique<GBufferPass>(context_);
    lightingPass_ = std::make_unique<LightingPass>(context_);
    shadingTables_ = std::make_unique<ShadingTables>(context_);
    nonFinite_ = std::make_unique<NonFiniteGuard>(context_);
    transparentPass_ = std::make_unique<ForwardTransparentPass>(
        context_, forwardMsaaSamples(context_, options_.msaaSamples));
    tonemapPass_ = std::make_unique<TonemapPass>(context_);
    if (options_.aa == AntiAliasing::Fxaa) fxaaPass_ = std::make_unique<FxaaPass>(context_);
    shadowPass_ = std::make_unique<ShadowPass>(context_);
    skyOcclusionPass_ = std::make_unique<SkyOcclusionPass>(context_);  // pipeline when used
    // The features, in frame order within each run.
    addFeature(FeatureRun::BeforeGeometry, std::make_unique<SkinningFeature>(context_));
    addFeature(FeatureRun::BeforeLighting, std::make_unique<AmbientOcclusionFeature>(context_));
    addFeature(FeatureRun::OverLitFrame, std::make_unique<SsrFeature>(context_));
    addFeature(FeatureRun::OverLitFrame, std::make_unique<VolumetricsFeature>(context_));
    addFeature(FeatureRun::OverLitFrame, std::make_unique<ScatteringFeature>(context_));
    addFeature(FeatureRun::OverLitFrame, std::make_unique<HairFeature>(context_));
    addFeature(FeatureRun::OverLitFrame, std::make_unique<WireFeature>(context_));
    addFeature(FeatureRun::AfterScene, std::make_unique<TaaFeature>(context_));
    addFeature(FeatureRun::AfterScene, std::make_unique<GbaaFeature>(context_));
    auto autoExposure = std::make_unique<AutoExposureFeature>(context_);
    autoExposure_ = autoExposure.get();  // the frame's exposure comes from it
    addFeature(FeatureRun::AfterScene, std::move(autoExposure));
    addFeature(FeatureRun::AfterScene, std::make_unique<BloomFeature>(context_));
}

void Renderer::diagnoseNonFiniteNextFrame() {
    nonFinite_->diagnoseNextFrame();
}

const EnvironmentBrdfLut* Renderer::environmentBrdfLut() const {
    return shadingTables_->brdfLut();
}

uint32_t Renderer::scaledSize(uint32_t outputSize, float scale) {
    // Anything but a fraction in (0, 1] renders at the output size.
    if (!(scale > 0.0f && scale < 1.0f)) return outputSize;
    return std::max(1u, uint32_t(std::lround(double(outputSize) * scale)));
}

Renderer::~Renderer() {
    shadingTables_.reset();
}

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
    declaredWork_ = {};
    FrameGraph& g = *graph_;
    // The atmosphere's tables come first; its sky cube is the environment the frame lights with.
    if (inputs.scene.atmosphere) {
        if (!atmospherePass_) {
            atmospherePass_ = std::make_unique<AtmospherePass>(context_, options_.atmosphere);
        }
        atmospherePass_->declareTables(g, AtmospherePass::frameOf(inputs.scene));
        resources.setEnvironment(atmospherePass_->environment());
    }
    LightingFeatures features = featuresOf(inputs.scene, resources, options_);
    // The reference samples the sky by a luminance table read back from its cube; the
    // atmosphere's first cube is rendered in this frame, so that frame lights by the split
    // sum and the reference starts with the next one.
    if (features.ibl == IblMode::Reference && atmospherePass_ && inputs.scene.atmosphere &&
        !atmospherePass_->environmentReadable()) {
        features.ibl = IblMode::SplitSum;
        std::fprintf(stderr,
                     "note: --ibl reference starts on the second frame: the atmosphere's sky "
                     "cube is rendered in the first\n");
    }
    // Shadow maps for the lights that cast; none, and the variant leaves shadows out.
    // Every draw's world box, once: the shadow views' and the camera's culling read it.
    const std::vector<WorldBounds> drawBounds = worldBoundsOf(inputs.scene, resources);
    features.shadows =
        shadowPass_->prepare(inputs.scene, resources, drawBounds, options_, width_, height_);
    for (const LightInstance& l : inputs.scene.lights) {
        if (!features.shadows || !l.light.castShadows) continue;
        (inEveryCluster(l.light) ? features.directionalShadows : features.localShadows) = true;
    }
    features.lightLoops =
        lightLoopsFor(inputs.scene.lights, shadowPass_->lightsWithMaps(), features.clustered);
    // Sky occlusion's maps: rendered when the static casters change, else kept.
    const SkyOcclusionMode skyOcclusion = options_.skyOcclusion == SkyOcclusionMode::Off &&
                                                  options_.skyOcclusionWithAtmosphere &&
                                                  inputs.scene.atmosphere
                                              ? SkyOcclusionMode::On
                                              : options_.skyOcclusion;
    if (skyOcclusion != SkyOcclusionMode::Off && features.ibl) {
        features.skyOcclusion = skyOcclusionPass_->prepare(inputs.scene, resources, skyOcclusion);
    }
    lightingPass_->setFeatures(features);
    shadingTables_->prepare(features, resources, stats_);
    features_ = features.names();
    // Layers blend in the G-buffer pass only; the lighting variant does not change with them.
    // The draws the camera sees, each at its level of detail: the G-buffer and forward passes
    // record no other. The sides widen by two pixels for TAA's jitter, which moves the image
    // after this test. --culling off: a frustum that holds everything.
    const CameraView& view = inputs.scene.camera;
    const ViewFrustum frustum = options_.culling
                                    ? viewFrustumOf(view.projection * view.view,
                                                    {4.0f / float(width_), 4.0f / float(height_)})
                                    : ViewFrustum{};
    const std::vector<uint8_t> visible = drawsInView(
        inputs.scene, resources, drawBounds, frustum,
        perspectiveLodView(view.position, view.projection, float(height_), options_.lodPixelError));
    stats_.draws = uint32_t(visible.size());
    stats_.drawsCulled = uint32_t(std::count(visible.begin(), visible.end(), kDrawCulled));
    for (size_t i = 0; i < visible.size(); ++i) {
        if (visible[i] != kDrawCulled)
            declaredWork_.triangles +=
                resources.mesh(inputs.scene.draws[i].mesh).lods[visible[i]].indexCount / 3;
    }
    gbufferPass_->prepare(inputs.scene, resources, visible,
                          usesMaterialLayers(inputs.scene, resources),
                          features.materialExtensions(), options_.aa == AntiAliasing::Gbaa,
                          nearestFirst(visible, drawBounds, view.position));
    if (gbufferPass_->materialLayers()) features_.push_back("material_layers");
    // Blended draws leave the G-buffer for the forward pass; none, and it records nothing.
    uploadFrameData(inputs);
    {  // the camera block carries sky occlusion's sphere and layout
        GpuCamera* camera = static_cast<GpuCamera*>(camera_->buffer().mapped());
        camera->skyOcclusionSphere =
            features.skyOcclusion ? skyOcclusionPass_->sphere() : glm::vec4(0.0f);
        camera->skyOcclusionLayout =
            features.skyOcclusion ? skyOcclusionPass_->layout() : glm::uvec4(0u);
    }
    const bool blended = transparentPass_->prepare(inputs.scene, resources, visible, features,
                                                   camera_->previousWorlds());
    stats_.lights = lights_->count();
    stats_.lightsRewritten = lights_->rewrittenLastUpdate();
    stats_.lightAssignMs = 0.0;
    stats_.shadowedLights = shadowPass_->stats().shadowedLights;
    stats_.shadowMapsRendered = shadowPass_->stats().mapsRendered;
    stats_.shadowMapsCached = shadowPass_->stats().mapsCached;
    stats_.shadowMapsKept = shadowPass_->stats().mapsKept;
    stats_.shadowAtlasUsed = shadowPass_->stats().atlasUsed;
    stats_.shadowCasterDraws = shadowPass_->stats().casterDraws;
    declaredWork_.shadowTriangles = shadowPass_->stats().casterTriangles;
    if (!features.clustered) clusters_->usePlaceholders();

    SceneHandles h;
    h.hdr = {hdrId, 0};
    for (size_t i = 0; i < h.color.size(); ++i) {
        h.color[i] = g.createImage(GBufferTargets::kColorNames[i],
                                   GBufferTargets::colorDesc(i, width_, height_));
    }
    h.depth = g.createImage("gbuffer.depth", GBufferTargets::depthDesc(width_, height_));
    h.motion =
        g.createImage(GBufferTargets::kMotionName, GBufferTargets::motionDesc(width_, height_));
    h.extended = features.materialExtensions();
    if (h.extended) {
        h.anisotropy = g.createImage(
            "gbuffer.anisotropy",
            GBufferTargets::extensionDesc(GBufferTargets::kAnisotropyFormat, width_, height_));
        h.clearCoat = g.createImage(
            "gbuffer.clear_coat",
            GBufferTargets::extensionDesc(GBufferTargets::kClearCoatFormat, width_, height_));
    }
    h.hasEdges = options_.aa == AntiAliasing::Gbaa;
    h.separateEdges = GBufferPass::separateEdges(h.extended, h.hasEdges);
    if (h.hasEdges) {
        h.edges = g.createImage(
            GBufferTargets::kEdgesName,
            GBufferTargets::extensionDesc(GBufferTargets::kEdgesFormat, width_, height_));
    }
    h.camera = g.importBuffer("camera", &camera_->buffer());
    h.lights = g.importBuffer("lights", &lights_->buffer());
    ResourceHandle pairCounts =
        g.importBuffer("lighting.pair_counts", &pairCounts_, features.countLightPairs);
    if (features.countLightPairs) {  // the lighting pass adds its counts atomically
        auto p = g.addPass("lighting_counts_clear", PassKind::Device, [this](PassContext& ctx) {
            vkCmdFillBuffer(ctx.cmd(), pairCounts_.handle(), 0, VK_WHOLE_SIZE, 0);
        });
        pairCounts = p.write(pairCounts, Use::TransferDst);
    }
    // The features get what the frame so far gives them (the blackboard, filled as it goes).
    FrameBlackboard& board = *board_;
    board.clear();
    FeatureFrame frame{g,       inputs,   resources, options_,  width_,
                       height_, features, board,     features_, declaredWork_};
    stats_.deformedDraws = uint32_t(inputs.scene.deforms.size());
    declareRun(frame, FeatureRun::BeforeGeometry);
    const DeformedVertices* deformedVertices = board.find<DeformedVertices>();
    const ResourceHandle deformed = deformedVertices ? deformedVertices->buffers : ResourceHandle{};
    auto readDeformed = [deformed](FrameGraph::PassBuilder& p) {
        if (deformed.valid()) p.read(deformed, Use::VertexInput);
    };

    // Shadows: the atlas keeps its maps between frames (cached tiles), read-only between uses.
    ResourceHandle shadowAtlas, shadowViews, shadowLights;
    if (features.shadows) {
        constexpr ImageState kShadowRead{
            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
            VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
            VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};
        shadowAtlas =
            g.importImage("shadow_atlas", &shadowPass_->atlas(),
                          shadowPass_->atlasHoldsMaps() ? kShadowRead : ImageState{}, kShadowRead);
        shadowViews = g.importBuffer("shadow_views", &shadowPass_->viewBuffer());
        shadowLights = g.importBuffer("shadow_lights", &shadowPass_->lightBuffer());
        if (shadowPass_->rendersThisFrame()) {
            auto p = g.addPass("shadows", PassKind::Device,
                               [this, &inputs, &resources](PassContext& ctx) {
                                   shadowPass_->record(ctx.cmd(), inputs.scene, resources);
                               });
            readDeformed(p);
            shadowAtlas = p.write(shadowAtlas, Use::DepthWrite);
        }
    }
    const ShadowDescriptors shadowDescriptors = shadowPass_->descriptors(features.shadows);
    ResourceHandle skyOcclusionAtlas;
    VkDescriptorImageInfo skyOcclusionDescriptor{};
    stats_.skyOcclusionRebuilt = false;
    if (features.skyOcclusion) {
        constexpr ImageState kSkyRead{VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                      VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                      VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};
        skyOcclusionAtlas =
            g.importImage("sky_occlusion_atlas", &skyOcclusionPass_->atlas(),
                          skyOcclusionPass_->atlasHoldsMaps() ? kSkyRead : ImageState{}, kSkyRead);
        if (skyOcclusionPass_->rendersThisFrame()) {
            stats_.skyOcclusionRebuilt = true;
            auto p = g.addPass("sky_occlusion", PassKind::Device,
                               [this, &inputs, &resources](PassContext& ctx) {
                                   skyOcclusionPass_->record(ctx.cmd(), inputs.scene, resources);
                               });
            skyOcclusionAtlas = p.write(skyOcclusionAtlas, Use::DepthWrite);
        }
        skyOcclusionDescriptor = skyOcclusionPass_->descriptor(true);
    } else {
        skyOcclusionDescriptor = skyOcclusionPass_->descriptor(false);
    }
    const SceneHandles ids = h;  // resource ids for the passes to look up
    auto gbufferViews = [ids](PassContext& ctx) {
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
    };
    {
        auto p =
            g.addPass("gbuffer", PassKind::Device,
                      [this, gbufferViews, ids, &inputs, &resources](PassContext& ctx) {
                          gbufferPass_->record(ctx.cmd(), gbufferViews(ctx), ctx.image(ids.hdr),
                                               inputs.clearRadiance, inputs.scene, resources,
                                               camera_->buffer(), camera_->previousWorlds());
                      });
        // GBAA's geometry stage reads the target size from the camera block too.
        p.read(h.camera, Use::Uniform,
               kRasterStages | (h.hasEdges ? VK_PIPELINE_STAGE_2_GEOMETRY_SHADER_BIT
                                           : VkPipelineStageFlags2(0)));
        readDeformed(p);
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
            "gbuffer_edges", PassKind::Device, [this, ids, &inputs, &resources](PassContext& ctx) {
                gbufferPass_->recordEdges(ctx.cmd(), ctx.image(ids.edges), ctx.image(ids.depth),
                                          inputs.scene, resources, camera_->buffer(),
                                          camera_->previousWorlds());
            });
        p.read(h.camera, Use::Uniform, kRasterStages | VK_PIPELINE_STAGE_2_GEOMETRY_SHADER_BIT);
        readDeformed(p);
        p.read(h.depth, Use::DepthRead);
        h.edges = p.write(h.edges, Use::ColorAttachment);
    }
    if (features.clustered) {
        h.clusters =
            clusters_->declare(g,
                               {&inputs, h.depth, h.camera, h.lights, &camera_->buffer(),
                                &lights_->buffer(), lights_->count(), lights_->capacity(),
                                blended ? transparentPass_.get() : nullptr, &resources, deformed},
                               stats_);
    }
    // What every lit pass reads beside its own inputs (the lighting pass in its compute stage,
    // hair, wires and blended surfaces in their fragment stage).
    const LitInputHandles litReads{h.camera,         h.lights,         features.clustered,
                                   h.clusters,       features.shadows, shadowAtlas,
                                   shadowViews,      shadowLights,     features.skyOcclusion,
                                   skyOcclusionAtlas};

    const EnvironmentDescriptors environment = shadingTables_->describe(features, resources);
    const float skyIntensity = inputs.scene.skyIntensity;
    const LitInputs lit{&camera_->buffer(), &lights_->buffer(), clusters_.get(),       environment,
                        skyIntensity,       shadowDescriptors,  skyOcclusionDescriptor};
    // Ambient occlusion between the G-buffer and lighting; then SSR, volumetrics, light shafts,
    // hair and wires over the lit frame and its medium, under the blended surfaces (which then
    // see the hair's depth); then the post features on the HDR target (recordFrame).
    SceneTargets& targets = board.put(SceneTargets{h.hdr, h.depth, h.motion, h.camera});
    board.put(GBufferFrame{h.color, h.hasEdges ? std::optional(h.edges) : std::nullopt});
    board.put(LitFrame{lit, litReads, lights_->count(), lights_->capacity(),
                       shadingTables_->brdfLut() != nullptr});
    if (features.shadows) {
        board.put(ShadowFrame{shadowPass_.get(), shadowAtlas, shadowViews, shadowLights});
    }
    declareRun(frame, FeatureRun::BeforeLighting);
    const float aoIntensity = std::clamp(inputs.scene.aoIntensity, 0.0f, 1.0f);
    if (!board.find<AmbientOcclusionFrame>())
        board.put(AmbientOcclusionFrame{{}, {}, 0, aoIntensity});
    const std::optional<ResourceHandle> occlusion = board.get<AmbientOcclusionFrame>().occlusion;
    const std::optional<ResourceHandle> specularOcclusion =
        board.get<AmbientOcclusionFrame>().specular;
    const bool aoMultiBounce = options_.aoSettings.multiBounce;
    {
        auto p = g.addPass(
            "lighting", PassKind::Device,
            [this, gbufferViews, ids, lit, occlusion, specularOcclusion, aoIntensity,
             aoMultiBounce](PassContext& ctx) {
                const GBufferTargets gbuffer = gbufferViews(ctx);
                LightingPass::Inputs lighting{&gbuffer, ctx.image(ids.hdr), lit, &pairCounts_};
                lighting.lightCount = lights_->count();
                lighting.referenceSamples = options_.referenceSamples;
                if (occlusion) lighting.ambientOcclusion = ctx.image(*occlusion);
                if (specularOcclusion) {
                    lighting.specularOcclusion = ctx.image(*specularOcclusion);
                }
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
        litReads.declareReads(p, kComputeStage);
        if (occlusion) p.read(*occlusion, Use::Sampled);
        if (specularOcclusion) p.read(*specularOcclusion, Use::Sampled);
        if (features.countLightPairs) p.write(pairCounts, Use::StorageReadWrite);  // atomics
        h.hdr = p.write(h.hdr, Use::StorageReadWrite);
    }
    if (inputs.scene.atmosphere) {
        features_.push_back("atmosphere");
        h.hdr = atmospherePass_->declareBackground(g, h.camera, h.depth, h.hdr, camera_->buffer());
    }
    targets.hdr = h.hdr;
    const IntegratedFroxels& froxelPlan =
        board.put(declareIntegratedFroxels(g, inputs.scene, options_, width_, height_, blended));
    declareRun(frame, FeatureRun::OverLitFrame);
    h.hdr = targets.hdr;
    h.depth = targets.depth;
    const std::optional<ResourceHandle> froxels = froxelPlan.buffer;
    if (blended) {
        // MSAA: multisampled copies of the targets, made only for frames with blended draws.
        const VkSampleCountFlagBits samples = transparentPass_->samples();
        const bool msaa = samples != VK_SAMPLE_COUNT_1_BIT;
        ResourceHandle msaaHdr, msaaMotion, msaaDepth;
        if (msaa) {
            msaaHdr = g.createImage("forward.msaa_hdr",
                                    ForwardTransparentPass::msaaHdrDesc(width_, height_, samples));
            msaaMotion =
                g.createImage("forward.msaa_motion",
                              ForwardTransparentPass::msaaMotionDesc(width_, height_, samples));
            msaaDepth = g.createImage("forward.msaa_depth", ForwardTransparentPass::msaaDepthDesc(
                                                                width_, height_, samples));
        }
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
            features_.push_back("forward_msaa");
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
        readDeformed(p);
        litReads.declareReads(p, kFragmentStage);
        h.hdr = p.write(h.hdr, Use::ColorAttachment);
        h.motion = p.write(h.motion, Use::ColorAttachment);
        features_.push_back("forward_transparency");
    }
    targets.hdr = h.hdr;
    targets.motion = h.motion;
    return h.hdr.version;
}

void Renderer::addFeature(FeatureRun run, std::unique_ptr<RenderFeature> feature) {
    renderFeatures_.push_back(std::move(feature));
    featureRuns_.push_back(run);
    featureDeclared_.push_back(false);
}

void Renderer::declareRun(FeatureFrame& frame, FeatureRun run) {
    for (size_t i = 0; i < renderFeatures_.size(); ++i) {
        if (featureRuns_[i] != run) continue;
        featureDeclared_[i] = renderFeatures_[i]->active(frame);
        if (featureDeclared_[i]) {
            renderFeatures_[i]->declare(frame);
        } else {
            renderFeatures_[i]->restartHistory();  // a frame without it breaks its sequence
        }
    }
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
    g.clear();
    ResourceHandle hdr = g.importImage("hdr", &hdr_, kDiscardAfterCopies, kReadyToCopy);
    ResourceHandle ldr = g.importImage("ldr", &ldr_, kDiscardAfterCopies, kReadyToCopy);
    const bool sceneFrame = !inputs.testTriangleRadiance && resources;
    if (!sceneFrame) {
        const std::array<float, 4> clear = inputs.clearRadiance;
        const std::array<float, 4> radiance = inputs.testTriangleRadiance.value_or(clear);
        auto p =
            g.addPass("triangle", PassKind::Device, [this, hdr, clear, radiance](PassContext& ctx) {
                trianglePass_->record(ctx.cmd(), ctx.image(hdr), clear, radiance);
            });
        hdr = p.write(hdr, Use::ColorAttachment);
        features_ = {"test_triangle"};
    } else {
        hdr.version = declareScene(inputs, *resources, hdr.id);
        if (options_.captureMotionVectors) declareMotionCapture(board_->get<SceneTargets>().motion);
    }
    // Auto exposure reads the histogram of the previous frame, which begin() waited for.
    float ev100 = inputs.scene.camera.ev100;
    stats_.exposureEv100 = ev100;
    stats_.adaptedEv100 = ev100;
    if (options_.exposure == ExposureMode::Auto && sceneFrame) {
        ev100 = autoExposure_->ev100(inputs, options_.autoExposure, stats_);
    }
    const float exposure = exposureFromEv100(ev100);
    if (sceneFrame) {
        // The post features (TAA, GBAA, the exposure histogram, bloom) on the scene's HDR
        // target, as the scene's passes left it.
        FrameBlackboard& board = *board_;
        SceneTargets& targets = board.get<SceneTargets>();
        targets.hdr = hdr;
        board.put(FrameExposure{exposure});
        FeatureFrame frame{
            g,     inputs,    *resources,   options_, width_, height_, lightingPass_->features(),
            board, features_, declaredWork_};
        declareRun(frame, FeatureRun::AfterScene);
        hdr = targets.hdr;
    } else {
        for (const std::unique_ptr<RenderFeature>& feature : renderFeatures_)
            feature->restartHistory();  // a frame without the scene breaks every sequence
    }
    if (upscalePass_) {
        features_.push_back("upscale");
        ResourceHandle output =
            g.importImage("hdr.output", &outputHdr_, kDiscardAfterCopies, kReadyToCopy);
        auto p = g.addPass("upscale", PassKind::Device, [this, hdr, output](PassContext& ctx) {
            upscalePass_->record(ctx.cmd(), ctx.image(hdr), ctx.image(output));
        });
        p.read(hdr, Use::Sampled);
        hdr = p.write(output, Use::StorageWrite);
    }
    if (nonFinite_->checks(options_.checkNonFinite)) {
        nonFinite_->declareCheck(g, hdr);
    } else {
        nonFinite_->skipCheck();
    }
    features_.push_back("tonemap_aces");
    {
        // FXAA reads the tonemapped image from a transient and writes the LDR target.
        ResourceHandle tonemapped = ldr;
        if (fxaaPass_) {
            tonemapped = g.createImage(
                "fxaa.input", {VK_FORMAT_R8G8B8A8_UNORM, outputWidth_, outputHeight_, 1, false,
                               VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT});
        }
        auto p = g.addPass(
            "tonemap", PassKind::Device, [this, hdr, tonemapped, exposure](PassContext& ctx) {
                tonemapPass_->record(ctx.cmd(), ctx.image(hdr), ctx.image(tonemapped), exposure);
            });
        p.read(hdr, Use::StorageRead);
        tonemapped = p.write(tonemapped, Use::StorageWrite);
        if (fxaaPass_) {
            features_.push_back("fxaa");
            auto f = g.addPass("fxaa", PassKind::Device, [this, tonemapped, ldr](PassContext& ctx) {
                fxaaPass_->record(ctx.cmd(), ctx.image(tonemapped), ctx.image(ldr));
            });
            f.read(tonemapped, Use::Sampled);
            ldr = f.write(ldr, Use::StorageWrite);
        } else {
            ldr = tonemapped;
        }
    }
    if (!inputs.text.empty()) {
        if (!debugTextPass_) debugTextPass_ = std::make_unique<DebugTextPass>(context_);
        const uint32_t glyphs = debugTextPass_->prepare(inputs.text, outputWidth_, outputHeight_);
        if (glyphs > 0) {
            features_.push_back("debug_text");
            const ResourceHandle text =
                g.importBuffer("debug_text.glyphs", &debugTextPass_->buffer());
            auto p =
                g.addPass("debug_text", PassKind::Device, [this, ldr, glyphs](PassContext& ctx) {
                    debugTextPass_->record(ctx.cmd(), ctx.image(ldr), glyphs);
                });
            p.read(text, Use::StorageRead);
            p.write(ldr, Use::StorageReadWrite);  // draws over the tonemapped pixels
        }
    }
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
    if (nonFinite_->declareProbes(g)) features_.push_back("nonfinite_probes");
    const double recordMs = millisecondsSince(start);
    executor_->execute(g, submitter, cmd);
    recorded_ = sceneFrame ? RecordedFrame::Scene : RecordedFrame::TestTriangle;
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
