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
};

// The reference: every light marched per pixel through the medium.
void declareReference(MediumDeclaration& m) {
    FeatureFrame& frame = m.frame;
    VolumetricsPass* pass = m.pass;
    FrameGraph& graph = m.frame.graph;
    SceneTargets& targets = m.targets;
    const VolumetricsPass::Inputs& volume = m.volume;
    const ShadowDescriptors& shadowDescriptors = m.shadowDescriptors;
    frame.features.push_back("volumetrics_reference");
    auto p = graph.addPass("volumetrics_reference", PassKind::Device,
                           [pass, hdr = targets.hdr, depth = targets.depth, volume,
                            shadowDescriptors](PassContext& ctx) {
                               VolumetricsPass::Inputs in = volume;
                               in.depth = ctx.image(depth);
                               in.hdr = ctx.image(hdr);
                               in.shadows = &shadowDescriptors;
                               pass->recordReference(ctx.cmd(), in);
                           });
    m.readLights(p);
    p.read(targets.depth, Use::Sampled);
    targets.hdr = p.write(targets.hdr, Use::StorageReadWrite);
}

// The fog's grid: lit per froxel, then integrated front to back into froxels.buffer.
void declareFroxelLight(MediumDeclaration& m, bool volumes) {
    FeatureFrame& frame = m.frame;
    VolumetricsPass* pass = m.pass;
    FrameGraph& graph = m.frame.graph;
    SceneTargets& targets = m.targets;
    IntegratedFroxels& froxels = m.froxels;
    const VolumetricsPass::Inputs& volume = m.volume;
    const ShadowDescriptors& shadowDescriptors = m.shadowDescriptors;
    if (!volumes) frame.features.push_back("volumetrics_froxels");
    if (froxels.sunChannel) frame.features.push_back("volumetrics_froxel_sun");
    const VkDeviceSize bytes =
        VolumetricsPass::froxelBufferBytes(volume.grid) * (froxels.sunChannel ? 2 : 1);
    ResourceHandle medium =
        graph.createBuffer("volumetrics.froxel_medium", bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    const ResourceHandle integrated = *froxels.buffer;
    auto light = graph.addPass("volumetrics_froxel_light", PassKind::Device,
                               [pass, medium, volume, shadowDescriptors](PassContext& ctx) {
                                   VolumetricsPass::Inputs in = volume;
                                   in.shadows = &shadowDescriptors;
                                   pass->recordFroxelLight(ctx.cmd(), in, ctx.buffer(medium));
                               });
    m.readLights(light);
    light.read(graph.importBuffer("volumetrics.froxel_bins", &pass->froxelBins()),
               Use::StorageRead);
    medium = light.write(medium, Use::StorageWrite);
    auto integrate =
        graph.addPass("volumetrics_froxel_integrate", PassKind::Device,
                      [pass, medium, integrated, volume](PassContext& ctx) {
                          pass->recordFroxelIntegrate(ctx.cmd(), volume, ctx.buffer(medium),
                                                      ctx.buffer(integrated));
                      });
    integrate.read(targets.camera, Use::Uniform);
    integrate.read(medium, Use::StorageRead);
    froxels.buffer = integrate.write(integrated, Use::StorageWrite);
}

// The integrated grid over the lit frame, by depth.
void declareFroxelComposite(MediumDeclaration& m) {
    VolumetricsPass* pass = m.pass;
    FrameGraph& graph = m.frame.graph;
    SceneTargets& targets = m.targets;
    IntegratedFroxels& froxels = m.froxels;
    const VolumetricsPass::Inputs& volume = m.volume;
    auto composite = graph.addPass("volumetrics_composite", PassKind::Device,
                                   [pass, hdr = targets.hdr, depth = targets.depth,
                                    integrated = *froxels.buffer, volume](PassContext& ctx) {
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

// Per-light volumes (Vos, GPU Pro 5), or the sun marched over the froxels: marched at half
// resolution (or rasterised as proxy meshes), blurred and composited.
void declareVolumes(MediumDeclaration& m, bool volumes, bool volumeProxies) {
    FeatureFrame& frame = m.frame;
    VolumetricsPass* pass = m.pass;
    FrameGraph& graph = m.frame.graph;
    SceneTargets& targets = m.targets;
    const VolumetricsPass::Inputs& volume = m.volume;
    const ShadowDescriptors& shadowDescriptors = m.shadowDescriptors;
    const uint32_t width = m.frame.width;
    const uint32_t height = m.frame.height;
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
                          [pass, depth = targets.depth, marched, proxyDepth, volume,
                           shadowDescriptors](PassContext& ctx) {
                              VolumetricsPass::Inputs in = volume;
                              in.depth = ctx.image(depth);
                              in.shadows = &shadowDescriptors;
                              pass->recordVolumesProxies(ctx.cmd(), in, ctx.image(marched),
                                                         ctx.image(proxyDepth));
                          });
        m.readLights(proxies, kRasterStages);
        proxies.read(graph.importBuffer("volumetrics.proxy_instances", &pass->proxyInstances()),
                     Use::StorageRead, kRasterStages);
        proxies.read(targets.depth, Use::Sampled, kFragmentStage);
        marched = proxies.write(marched, Use::ColorAttachment);
        proxies.write(proxyDepth, Use::DepthWrite);
    } else {
        auto march = graph.addPass(
            "volumetrics_volumes_march", PassKind::Device,
            [pass, depth = targets.depth, marched, volume, shadowDescriptors](PassContext& ctx) {
                VolumetricsPass::Inputs in = volume;
                in.depth = ctx.image(depth);
                in.shadows = &shadowDescriptors;
                pass->recordVolumesMarch(ctx.cmd(), in, ctx.image(marched));
            });
        m.readLights(march);
        march.read(graph.importBuffer("volumetrics.volume_bins", &pass->volumeBins()),
                   Use::StorageRead);
        march.read(targets.depth, Use::Sampled);
        marched = march.write(marched, Use::StorageWrite);
    }
    auto blur = graph.addPass("volumetrics_volumes_blur", PassKind::Device,
                              [pass, marched, blurred, volume](PassContext& ctx) {
                                  pass->recordVolumesBlur(ctx.cmd(), volume, ctx.image(marched),
                                                          ctx.image(blurred));
                              });
    blur.read(targets.camera, Use::Uniform);
    blur.read(marched, Use::StorageRead);
    blurred = blur.write(blurred, Use::StorageWrite);
    auto composite =
        graph.addPass("volumetrics_volumes_composite", PassKind::Device,
                      [pass, hdr = targets.hdr, depth = targets.depth, blurred, volume,
                       volumes](PassContext& ctx) {
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
    const bool volumeProxies = marchVolumes && options.volumetricsSettings.volumeProxies;
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
        declareReference(m);
        return;
    }
    // Per-light volumes light only opaque surfaces; blended ones and wires read the froxel grid,
    // made for them in frames that have them.
    const bool volumes = options.volumetrics == VolumetricsMode::Volumes;
    if (froxels.fogFroxels) declareFroxelLight(m, volumes);
    // The froxels' composite first: the sun marched over them only adds its light.
    if (!volumes) declareFroxelComposite(m);
    if (volumes || froxels.sunMarched) declareVolumes(m, volumes, volumeProxies);
}

}  // namespace candela::render
