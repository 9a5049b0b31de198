#include "passes/volumetrics/volumetrics_feature.h"

#include "candela/render/frame_inputs.h"
#include "features/scene_targets.h"
#include "frame_graph/frame_graph_executor.h"
#include "lit_inputs.h"
#include "passes/shadows/shadow_frame.h"
#include "passes/volumetrics/integrated_froxels.h"
#include "passes/volumetrics/volumetrics_pass.h"

namespace candela::render {

namespace {

// One frame's volumetric passes, declared from what VolumetricsFeature::declare gathered.
struct MediumDeclaration {
    FeatureFrame& frame;
    VolumetricsPass* pass;
    SceneTargets& targets;
    const LitFrame& lit;
    const ShadowFrame* shadows;
    IntegratedFroxels& froxels;
    VolumetricsPass::Inputs volume;
    ShadowDescriptors shadowDescriptors;
    ResourceHandle scales;  // the lights' scattering scales

    // What every pass that lights the medium reads.
    void readLights(FrameGraph::PassBuilder& p,
                    VkPipelineStageFlags2 stages = kComputeStage) const {
        p.read(targets.camera, Use::Uniform, stages);
        p.read(lit.reads.lights, Use::StorageRead, stages);
        p.read(scales, Use::StorageRead, stages);
        if (shadows) {
            p.read(shadows->atlas, Use::Sampled, stages);
            p.read(shadows->views, Use::StorageRead, stages);
            p.read(shadows->lights, Use::StorageRead, stages);
        }
    }
    // The reference: every light marched per pixel through the medium.
    void declareReference();
    // The fog's grid: lit per froxel, then integrated front to back into froxels.buffer.
    void declareFroxelLight(bool volumes);
    // The integrated grid over the lit frame, by depth.
    void declareFroxelComposite();
    // Per-light volumes (Vos, GPU Pro 5), or the sun marched over the froxels: marched at half
    // resolution (or rasterised as proxy meshes), blurred and composited.
    void declareVolumes(bool volumes, bool volumeProxies);
};

void MediumDeclaration::declareReference() {
    FrameGraph& graph = frame.graph;
    frame.features.push_back("volumetrics_reference");
    auto p = graph.addPass("volumetrics_reference", PassKind::Device,
                           [pass = pass, hdr = targets.hdr, depth = targets.depth, volume = volume,
                            shadowDescriptors = shadowDescriptors](PassContext& ctx) {
                               VolumetricsPass::Inputs in = volume;
                               in.depth = ctx.image(depth);
                               in.hdr = ctx.image(hdr);
                               in.shadows = &shadowDescriptors;
                               pass->recordReference(ctx.cmd(), in);
                           });
    readLights(p);
    p.read(targets.depth, Use::Sampled);
    targets.hdr = p.write(targets.hdr, Use::StorageReadWrite);
}

void MediumDeclaration::declareFroxelLight(bool volumes) {
    FrameGraph& graph = frame.graph;
    if (!volumes) frame.features.push_back("volumetrics_froxels");
    if (froxels.sunChannel) frame.features.push_back("volumetrics_froxel_sun");
    const VkDeviceSize bytes =
        VolumetricsPass::froxelBufferBytes(volume.grid) * (froxels.sunChannel ? 2 : 1);
    ResourceHandle medium =
        graph.createBuffer("volumetrics.froxel_medium", bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    const ResourceHandle integrated = *froxels.buffer;
    auto light = graph.addPass("volumetrics_froxel_light", PassKind::Device,
                               [pass = pass, medium, volume = volume,
                                shadowDescriptors = shadowDescriptors](PassContext& ctx) {
                                   VolumetricsPass::Inputs in = volume;
                                   in.shadows = &shadowDescriptors;
                                   pass->recordFroxelLight(ctx.cmd(), in, ctx.buffer(medium));
                               });
    readLights(light);
    light.read(graph.importBuffer("volumetrics.froxel_bins", &pass->froxelBins()),
               Use::StorageRead);
    medium = light.write(medium, Use::StorageWrite);
    auto integrate =
        graph.addPass("volumetrics_froxel_integrate", PassKind::Device,
                      [pass = pass, medium, integrated, volume = volume](PassContext& ctx) {
                          pass->recordFroxelIntegrate(ctx.cmd(), volume, ctx.buffer(medium),
                                                      ctx.buffer(integrated));
                      });
    integrate.read(targets.camera, Use::Uniform);
    integrate.read(medium, Use::StorageRead);
    froxels.buffer = integrate.write(integrated, Use::StorageWrite);
}

void MediumDeclaration::declareFroxelComposite() {
    FrameGraph& graph = frame.graph;
    auto composite =
        graph.addPass("volumetrics_composite", PassKind::Device,
                      [pass = pass, hdr = targets.hdr, depth = targets.depth,
                       integrated = *froxels.buffer, volume = volume](PassContext& ctx) {
                          VolumetricsPass::Inputs in = volume;
                          in.depth = ctx.image(depth);
                          in.hdr = ctx.image(hdr);
                          pass->recordComposite(ctx.cmd(), in, ctx.buffer(integrated));
                      });
    composite.read(targets.camera, Use::Uniform);
    composite.read(targets.depth, Use::Sampled);
    composite.read(*froxels.buffer, Use::StorageRead);
    targets.hdr = composite.write(targets.hdr, Use::StorageReadWrite);
}

void MediumDeclaration::declareVolumes(bool volumes, bool volumeProxies) {
    FrameGraph& graph = frame.graph;
    const uint32_t width = frame.width;
    const uint32_t height = frame.height;
    frame.features.push_back(volumes ? "volumetrics_volumes" : "volumetrics_sun_march");
    ResourceHandle marched = graph.createImage(
        "volumetrics.volumes_marched", VolumetricsPass::volumesDesc(width, height, volumeProxies));
    ResourceHandle blurred = graph.createImage("volumetrics.volumes_blurred",
                                               VolumetricsPass::volumesDesc(width, height));
    if (volumeProxies) {
        // Each light's proxy mesh rasterised at half resolution (Vos, GPU Pro 5).
        ResourceHandle proxyDepth = graph.createImage(
            "volumetrics.volumes_depth", VolumetricsPass::volumesDepthDesc(width, height));
        auto proxies =
            graph.addPass("volumetrics_volumes_proxies", PassKind::Device,
                          [pass = pass, depth = targets.depth, marched, proxyDepth, volume = volume,
                           shadowDescriptors = shadowDescriptors](PassContext& ctx) {
                              VolumetricsPass::Inputs in = volume;
                              in.depth = ctx.image(depth);
                              in.shadows = &shadowDescriptors;
                              pass->recordVolumesProxies(ctx.cmd(), in, ctx.image(marched),
                                                         ctx.image(proxyDepth));
                          });
        readLights(proxies, kRasterStages);
        proxies.read(graph.importBuffer("volumetrics.proxy_instances", &pass->proxyInstances()),
                     Use::StorageRead, kRasterStages);
        proxies.read(targets.depth, Use::Sampled, kFragmentStage);
        marched = proxies.write(marched, Use::ColorAttachment);
        proxies.write(proxyDepth, Use::DepthWrite);
    } else {
        auto march = graph.addPass("volumetrics_volumes_march", PassKind::Device,
                                   [pass = pass, depth = targets.depth, marched, volume = volume,
                                    shadowDescriptors = shadowDescriptors](PassContext& ctx) {
                                       VolumetricsPass::Inputs in = volume;
                                       in.depth = ctx.image(depth);
                                       in.shadows = &shadowDescriptors;
                                       pass->recordVolumesMarch(ctx.cmd(), in, ctx.image(marched));
                                   });
        readLights(march);
        march.read(graph.importBuffer("volumetrics.volume_bins", &pass->volumeBins()),
                   Use::StorageRead);
        march.read(targets.depth, Use::Sampled);
        marched = march.write(marched, Use::StorageWrite);
    }
    auto blur = graph.addPass("volumetrics_volumes_blur", PassKind::Device,
                              [pass = pass, marched, blurred, volume = volume](PassContext& ctx) {
                                  pass->recordVolumesBlur(ctx.cmd(), volume, ctx.image(marched),
                                                          ctx.image(blurred));
                              });
    blur.read(targets.camera, Use::Uniform);
    blur.read(marched, Use::StorageRead);
    blurred = blur.write(blurred, Use::StorageWrite);
    auto composite =
        graph.addPass("volumetrics_volumes_composite", PassKind::Device,
                      [pass = pass, hdr = targets.hdr, depth = targets.depth, blurred,
                       volume = volume, volumes](PassContext& ctx) {
                          VolumetricsPass::Inputs in = volume;
                          in.depth = ctx.image(depth);
                          in.hdr = ctx.image(hdr);
                          pass->recordVolumesComposite(ctx.cmd(), in, ctx.image(blurred), !volumes);
                      });
    composite.read(targets.camera, Use::Uniform);
    composite.read(targets.depth, Use::Sampled);
    composite.read(blurred, Use::StorageRead);
    targets.hdr = composite.write(targets.hdr, Use::StorageReadWrite);
}

}  // namespace

VolumetricsFeature::VolumetricsFeature(GpuContext& context) : context_(context) {}

VolumetricsFeature::~VolumetricsFeature() = default;

bool VolumetricsFeature::active(const FeatureFrame& frame) const {
    return frame.inputs.scene.fog && frame.options.volumetrics != VolumetricsMode::Off;
}

void VolumetricsFeature::declare(FeatureFrame& frame) {
    if (!pass_) pass_ = std::make_unique<VolumetricsPass>(context_);
    VolumetricsPass* pass = pass_.get();
    const RendererOptions& options = frame.options;
    FrameGraph& graph = frame.graph;
    const uint32_t width = frame.width;
    const uint32_t height = frame.height;
    SceneTargets& targets = frame.board.get<SceneTargets>();
    const LitFrame& lit = frame.board.get<LitFrame>();
    const ShadowFrame* shadows = frame.board.find<ShadowFrame>();
    IntegratedFroxels& froxels = frame.board.get<IntegratedFroxels>();
    const ShadowDescriptors shadowDescriptors = lit.inputs.shadows;
    const bool marchVolumes = options.volumetrics == VolumetricsMode::Volumes;
    const bool volumeProxies = marchVolumes && options.volumeProxies;
    const bool lightFroxels = froxels.fogFroxels;  // the mode, or blended surfaces to light
    VolumetricsPass::Uses uses;
    uses.reference = options.volumetrics == VolumetricsMode::Reference;
    uses.froxels = lightFroxels;
    uses.volumesMarch = (marchVolumes && !volumeProxies) || froxels.sunMarched;
    uses.volumesProxies = volumeProxies;
    pass->prepare(frame.inputs.scene.lights, frame.lighting.shadows, uses);
    VolumetricsPass::Inputs volume;
    volume.camera = lit.inputs.camera;
    volume.lights = lit.inputs.lights;
    volume.lightCount = lit.lightCount;
    volume.lightCapacity = lit.lightCapacity;
    volume.fog = *frame.inputs.scene.fog;
    volume.nearPlane = frame.inputs.scene.camera.nearPlane;
    volume.settings = options.volumetricsSettings;
    volume.froxelLightCap = options.froxelLightCap;
    volume.grid = VolumetricsPass::froxelGrid(width, height, volume.settings);
    if (froxels.fogFroxels) volume.grid = froxels.fogGrid;
    volume.froxelSunChannel = froxels.sunChannel;
    const ResourceHandle scales =
        graph.importBuffer("volumetrics.light_scales", &pass->lightScales());
    // Which lights each march tile or froxel cluster meets (the reference meets them all),
    // or the rasterised proxies' instances.
    pass->binLights(frame.inputs.scene.lights, frame.inputs.scene.camera, width, height, volume,
                    marchVolumes && !volumeProxies, lightFroxels, froxels.sunMarched);
    frame.work.froxelLightEvaluations = pass->binnedWork().froxelLightEvaluations;
    frame.work.volumeMarchSteps = pass->binnedWork().volumeMarchSteps;
    if (volumeProxies) {
        pass->buildProxies(frame.inputs.scene.lights, frame.inputs.scene.camera, width, height);
    }
    MediumDeclaration m{frame,   pass,   targets,           lit,   shadows,
                        froxels, volume, shadowDescriptors, scales};
    if (options.volumetrics == VolumetricsMode::Reference) {
        m.declareReference();
        return;
    }
    // Per-light volumes light only opaque surfaces; blended ones and wires read the froxel grid,
    // made for them in frames that have them.
    const bool volumes = options.volumetrics == VolumetricsMode::Volumes;
    if (froxels.fogFroxels) m.declareFroxelLight(volumes);
    // The froxels' composite first: the sun marched over them only adds its light.
    if (!volumes) m.declareFroxelComposite();
    if (volumes || froxels.sunMarched) m.declareVolumes(volumes, volumeProxies);
}

void VolumetricsFeature::collectStats(RendererStats& stats, bool) const {
    stats.volumetricsMs = passMilliseconds(stats, "volumetrics_");
}

}  // namespace candela::render
