#include "candela/render/renderer.h"

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstring>
#include <span>

#include "candela/ecs/job_system.h"
#include "candela/render/frame_submitter.h"
#include "candela/render/gpu_context.h"
#include "candela/render/scene_resources.h"
#include "clustered/cluster_grid.h"
#include "clustered/light_assignment.h"
#include "frame_graph/frame_graph.h"
#include "frame_graph/frame_graph_executor.h"
#include "gbuffer_targets.h"
#include "gpu_camera.h"
#include "ibl/environment_brdf_lut.h"
#include "ibl/environment_descriptors.h"
#include "ibl/environment_sampling_table.h"
#include "lights/gpu_light_buffer.h"
#include "passes/depth_occupancy/depth_occupancy_pass.h"
#include "passes/forward_transparent/forward_transparent_pass.h"
#include "passes/gbuffer/gbuffer_pass.h"
#include "passes/light_assignment/light_assignment_pass.h"
#include "passes/lighting/lighting_pass.h"
#include "passes/tonemap/tonemap_pass.h"
#include "passes/triangle/triangle_pass.h"
#include "vk/vk_check.h"

namespace candela::render {

const char* iblModeName(IblMode mode) {
    switch (mode) {
        case IblMode::SplitSum:
            return "split_sum";
        case IblMode::Mobile:
            return "mobile";
        case IblMode::Reference:
            return "reference";
    }
    return "unknown";
}

float exposureFromEv100(float ev100) {
    return 1.0f / (1.2f * std::exp2(ev100));
}

namespace {

using Clock = std::chrono::steady_clock;

// The shader variant a scene needs: only the shading models its drawn materials use and the
// light shapes its lights have.
LightingFeatures featuresOf(const FrameScene& scene, const SceneResources& resources,
                            const RendererOptions& options) {
    LightingFeatures f;
    f.clustered = options.lightCulling == LightCulling::Clustered;
    f.countLightPairs = options.countLightPairs;
    if (resources.environment()) f.ibl = options.ibl;
    for (const DrawItem& draw : scene.draws) {
        switch (resources.material(draw.material).shadingModel) {
            case content::ShadingModel::Subsurface:
                f.subsurface = true;
                break;
            case content::ShadingModel::Legacy:
                f.legacyDiffuseSpecular = true;
                break;
            default:
                break;
        }
    }
    for (const LightInstance& l : scene.lights) {
        if (l.light.type == content::LightType::Directional) continue;
        f.sphereLights |= l.light.sourceRadius > 0.0f;
        f.tubeLights |= l.light.sourceLength > 0.0f;
        f.spotLights |= l.light.type == content::LightType::Spot;
    }
    return f;
}

// Host-visible storage buffer of at least `bytes`; grows by doubling. True when it grew.
bool ensureBuffer(GpuContext& context, GpuBuffer& buffer, VkDeviceSize bytes) {
    bytes = std::max<VkDeviceSize>(bytes, 16);
    if (buffer.handle() && buffer.size() >= bytes) return false;
    VkDeviceSize size = std::max(bytes, buffer.size() * 2);
    buffer =
        GpuBuffer(context, size, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryLocation::HostVisible);
    return true;
}

// hdr and ldr: discarded at the start of a frame (the previous frame's copies out of them
// are fenced), left ready to be copied from (capture, swapchain blit) at its end.
constexpr ImageState kDiscardAfterCopies{VK_IMAGE_LAYOUT_UNDEFINED,
                                         VK_PIPELINE_STAGE_2_TRANSFER_BIT, 0};
constexpr ImageState kReadyToCopy{VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                                  VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT};
constexpr VkPipelineStageFlags2 kRasterStages = kVertexStage | kFragmentStage;

double millisecondsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

Renderer::Renderer(GpuContext& context, uint32_t width, uint32_t height,
                   const RendererOptions& options)
    : context_(context),
      options_(options),
      width_(width),
      height_(height),
      lightAssignment_(resolveLightAssignment(options, context)),
      graph_(std::make_unique<FrameGraph>()),
      executor_(std::make_unique<FrameGraphExecutor>(context)),
      cameraBuffer_(context, sizeof(GpuCamera), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                    MemoryLocation::HostVisible),
      lights_(std::make_unique<GpuLightBuffer>()),
      grid_(std::make_unique<ClusterGrid>()),
      assignment_(std::make_unique<LightAssignment>()),
      jobs_(std::make_unique<ecs::JobSystem>()) {
    createTargets();
    trianglePass_ = std::make_unique<TrianglePass>(context_);
    gbufferPass_ = std::make_unique<GBufferPass>(context_);
    occupancyPass_ = std::make_unique<DepthOccupancyPass>(context_);
    lightingPass_ = std::make_unique<LightingPass>(context_);
    environmentPlaceholders_ = std::make_unique<EnvironmentPlaceholders>(context_);
    transparentPass_ = std::make_unique<ForwardTransparentPass>(context_);
    tonemapPass_ = std::make_unique<TonemapPass>(context_);
    if (lightAssignment_ == LightAssignmentDevice::Gpu) {
        assignmentPass_ = std::make_unique<LightAssignmentPass>(context_);
    }
}

Renderer::~Renderer() {
    brdfLut_.reset();
    samplingTable_.reset();
}

LightAssignmentDevice Renderer::resolveLightAssignment(const RendererOptions& options,
                                                       const GpuContext& context) {
    if (options.lightAssignment != LightAssignmentDevice::Auto) return options.lightAssignment;
    // On a CPU device the "GPU" is the same cores: the job system's sort beats four compute
    // dispatches there (render/README.md, "CPU vs compute light assignment").
    return context.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU
               ? LightAssignmentDevice::Cpu
               : LightAssignmentDevice::Gpu;
}

void Renderer::resize(uint32_t width, uint32_t height) {
    width_ = width;
    height_ = height;
    createTargets();
}

void Renderer::createTargets() {
    // RGBA32F, not 16F: captures are compared at 1e-4..1e-5 relative, below half precision.
    hdr_ = GpuImage(context_, {VK_FORMAT_R32G32B32A32_SFLOAT, width_, height_, 1, false,
                               VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_STORAGE_BIT |
                                   VK_IMAGE_USAGE_TRANSFER_SRC_BIT});
    // Colour attachment too: UI overlays (candela::ui) draw onto the tonemapped image.
    ldr_ = GpuImage(context_, {VK_FORMAT_R8G8B8A8_UNORM, width_, height_, 1, false,
                               VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                   VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT});
    ensureBuffer(context_, pairCounts_,
                 VkDeviceSize(LightingPass::workgroupCount(width_, height_)) * 8);
}

void Renderer::uploadFrameData(const FrameInputs& inputs) {
    const FrameScene& scene = inputs.scene;
    lights_->update(context_, scene.lights, scene.changedLights, scene.lightsRestructured);
    const CameraView& view = scene.camera;
    *grid_ = ClusterGrid::make(options_.tileSize, options_.slices, width_, height_,
                               view.projection[0][0], view.projection[1][1], view.nearPlane,
                               view.farPlane);

    GpuCamera camera{};
    camera.viewProjection = view.projection * view.view;
    camera.inverseViewProjection = glm::inverse(camera.viewProjection);
    camera.cameraPosition = glm::vec4(view.position, 1.0f);
    camera.frameInfo = glm::uvec4(width_, height_, lights_->count(), lights_->capacity());
    std::memcpy(cameraBuffer_.mapped(), &camera, sizeof(camera));
}

void Renderer::assignLightsToClusters(const FrameInputs& inputs) {
    // The slicing the occupancy pass derived from the measured depth range, bit for bit.
    const auto* range = static_cast<const uint32_t*>(depthRange_.mapped());
    float sliceNear, logRatio;
    std::memcpy(&sliceNear, &range[2], sizeof(float));
    std::memcpy(&logRatio, &range[3], sizeof(float));
    grid_->setSlicing(sliceNear, logRatio);
    ClusterOccupancy occupancy;
    occupancy.tileMasks = {static_cast<const uint64_t*>(occupancy_.mapped()), grid_->tileCount()};
    occupancy.pixelBounds = {static_cast<const float*>(clusterBounds_.mapped()),
                             size_t(grid_->clusterCount()) * 6};
    // Ranges are written in place, only for the clusters that changed (light_assignment.h): a
    // new buffer starts from zeros.
    if (ensureBuffer(context_, clusterRanges_, VkDeviceSize(grid_->clusterCount()) * 8)) {
        std::memset(clusterRanges_.mapped(), 0, clusterRanges_.size());
        assignment_->rangedClusters.clear();
    }
    assignLights(*grid_, inputs.scene.lights, inputs.scene.camera.view, occupancy, jobs_.get(),
                 {static_cast<uint32_t*>(clusterRanges_.mapped()), clusterRanges_.size() / 4},
                 *assignment_);
    // The lists are sized exactly each frame, so a light is never dropped; growing the buffer
    // is what the overflow counter reports.
    if (ensureBuffer(context_, lightIndices_,
                     assignment_->lightIndices.size() * sizeof(uint32_t)) &&
        !assignment_->lightIndices.empty()) {
        ++stats_.lightListOverflows;
    }
    // A frame without lights has no list entries, and memcpy from an empty vector's null
    // data() is undefined even for 0 bytes (UBSan).
    if (!assignment_->lightIndices.empty()) {
        std::memcpy(lightIndices_.mapped(), assignment_->lightIndices.data(),
                    assignment_->lightIndices.size() * sizeof(uint32_t));
    }
    stats_.clusters = grid_->clusterCount();
    stats_.clustersOccupied = assignment_->occupiedClusters;
    stats_.lightClusterPairs = assignment_->assignedPairs;
}

void Renderer::prepareGpuAssignment(const FrameInputs& inputs) {
    absorbGpuListUsage();
    std::span<const LightInstance> lights = inputs.scene.lights;
    // Directional lights lead the index buffer, as on the CPU path; the device lists follow.
    std::vector<uint32_t>& directional = assignment_->lightIndices;
    directional.clear();
    for (uint32_t i = 0; i < lights.size(); ++i) {
        if (lights[i].light.type == content::LightType::Directional) directional.push_back(i);
    }
    assignment_->directionalCount = uint32_t(directional.size());
    if (gpuListEntriesWanted_ == 0) {
        // First frame: a guess (the floor benchmark needs under 8 entries per light); later
        // frames grow from what the previous one asked for.
        gpuListEntriesWanted_ = options_.initialGpuLightListEntries
                                    ? options_.initialGpuLightListEntries
                                    : std::max<uint32_t>(uint32_t(lights.size()) * 16, 1u << 16);
    }
    ensureBuffer(context_, lightIndices_,
                 VkDeviceSize(std::max<size_t>(gpuListEntriesWanted_, directional.size())) * 4);
    if (!directional.empty()) {  // data() may be null (see assignLightsToClusters)
        std::memcpy(lightIndices_.mapped(), directional.data(),
                    directional.size() * sizeof(uint32_t));
    }
    ensureBuffer(context_, clusterRanges_, VkDeviceSize(grid_->clusterCount()) * 8);
    gpuListCapacity_ = uint32_t(lightIndices_.size() / 4);
    gpuListPending_ = true;
    stats_.clusters = grid_->clusterCount();
}

void Renderer::absorbGpuListUsage() {
    // The frame that recorded the device assignment has completed (collectStats, or the next
    // recordFrame after FrameSubmitter::begin waited for it).
    if (!gpuListPending_) return;
    gpuListPending_ = false;
    const uint32_t requested = assignmentPass_->requestedEntries();
    stats_.lightClusterPairs = requested - assignment_->directionalCount;
    if (requested > gpuListCapacity_) {
        ++stats_.lightListOverflows;
        gpuListEntriesWanted_ = requested + requested / 4;
    }
    stats_.clustersOccupied = 0;
    const auto* masks = static_cast<const uint64_t*>(occupancy_.mapped());
    for (uint32_t t = 0; t < grid_->tileCount(); ++t) {
        stats_.clustersOccupied += uint32_t(std::popcount(masks[t]));
    }
}

// The handles of one frame's scene passes. Passes capture resource ids by value; the
// versions they read are declared through the builder.
struct Renderer::SceneHandles {
    std::array<ResourceHandle, 4> color;
    ResourceHandle depth, hdr, camera, lights;
    ResourceHandle depthRange, tileMasks, clusterBounds, clusterRanges, lightIndices;
};

void Renderer::declareClusterAssignment(const FrameInputs& inputs, SceneResources& resources,
                                        SceneHandles& h, bool blended) {
    FrameGraph& g = *graph_;
    const glm::mat4& projection = inputs.scene.camera.projection;
    const glm::vec2 projectionScale{projection[0][0], projection[1][1]};
    const bool onDevice = lightAssignment_ == LightAssignmentDevice::Gpu;
    ensureBuffer(context_, occupancy_, VkDeviceSize(grid_->tileCount()) * 8);
    ensureBuffer(context_, clusterBounds_, VkDeviceSize(grid_->clusterCount()) * 24);
    // Read on the CPU: by the host assignment pass, or (device path) for the stats.
    h.tileMasks = g.importBuffer("cluster.tile_masks", &occupancy_, onDevice);
    h.clusterBounds = g.importBuffer("cluster.bounds", &clusterBounds_);

    {
        auto p = g.addPass("depth_range_clear", PassKind::Device, [this](PassContext& ctx) {
            occupancyPass_->recordClearRange(ctx.cmd(), depthRange_);
        });
        h.depthRange = p.write(h.depthRange, Use::TransferDst);
    }
    {
        const ResourceHandle depth = h.depth;
        auto p = g.addPass("depth_range", PassKind::Device, [this, depth](PassContext& ctx) {
            occupancyPass_->recordMeasureRange(ctx.cmd(), ctx.image(depth), *grid_, depthRange_);
        });
        p.read(h.depth, Use::Sampled);
        h.depthRange = p.write(h.depthRange, Use::StorageReadWrite);
    }
    {
        const ResourceHandle depth = h.depth;
        auto p = g.addPass(
            "depth_occupancy", PassKind::Device, [this, depth, projectionScale](PassContext& ctx) {
                occupancyPass_->recordMarkOccupancy(ctx.cmd(), ctx.image(depth), *grid_,
                                                    projectionScale,
                                                    {&occupancy_, &clusterBounds_, &depthRange_});
            });
        p.read(h.depth, Use::Sampled);
        h.depthRange = p.write(h.depthRange, Use::StorageReadWrite);
        h.tileMasks = p.write(h.tileMasks, Use::StorageWrite);
        h.clusterBounds = p.write(h.clusterBounds, Use::StorageWrite);
    }
    if (blended) {
        ResourceHandle bounds =
            g.createBuffer("transparent.bounds", ForwardTransparentPass::boundsBytes(*grid_),
                           VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
        const ResourceHandle depth = h.depth;
        auto occupancyInputs = [this, depth, bounds, projectionScale](PassContext& ctx) {
            return ForwardTransparentPass::OccupancyInputs{
                ctx.image(depth), &cameraBuffer_,     &depthRange_, &occupancy_,
                &clusterBounds_,  ctx.buffer(bounds), grid_.get(),  projectionScale};
        };
        auto clear =
            g.addPass("transparent_bounds_clear", PassKind::Device,
                      [this, occupancyInputs](PassContext& ctx) {
                          transparentPass_->recordClearBounds(ctx.cmd(), occupancyInputs(ctx));
                      });
        bounds = clear.write(bounds, Use::TransferDst);
        auto mark = g.addPass("transparent_occupancy", PassKind::Device,
                              [this, occupancyInputs, &resources](PassContext& ctx) {
                                  transparentPass_->recordMarkOccupancy(ctx.cmd(), resources,
                                                                        occupancyInputs(ctx));
                              });
        mark.read(h.depth, Use::Sampled, kFragmentStage);
        mark.read(h.camera, Use::Uniform, kRasterStages);
        mark.read(h.depthRange, Use::StorageRead, kFragmentStage);
        bounds = mark.write(bounds, Use::StorageReadWrite, kFragmentStage);
        auto merge =
            g.addPass("transparent_occupancy_merge", PassKind::Device,
                      [this, occupancyInputs](PassContext& ctx) {
                          transparentPass_->recordMergeOccupancy(ctx.cmd(), occupancyInputs(ctx));
                      });
        merge.read(bounds, Use::StorageRead);
        h.tileMasks = merge.write(h.tileMasks, Use::StorageReadWrite);
        h.clusterBounds = merge.write(h.clusterBounds, Use::StorageReadWrite);
    }

    if (!onDevice) {
        // The frame splits here: the occupancy must be on the CPU before lights are assigned.
        auto p = g.addPass("light_assignment_cpu", PassKind::Host, [this, &inputs](PassContext&) {
            const Clock::time_point start = Clock::now();
            assignLightsToClusters(inputs);
            stats_.lightAssignMs = millisecondsSince(start);
        });
        p.read(h.tileMasks, Use::HostRead);
        p.read(h.clusterBounds, Use::HostRead);
        p.read(h.depthRange, Use::HostRead);
        h.clusterRanges = p.write(h.clusterRanges, Use::HostWrite);
        h.lightIndices = p.write(h.lightIndices, Use::HostWrite);
        return;
    }

    prepareGpuAssignment(inputs);
    const LightAssignmentPass::Inputs in{&lights_->buffer(),
                                         lights_->count(),
                                         lights_->capacity(),
                                         inputs.scene.camera.view,
                                         grid_.get(),
                                         width_,
                                         height_,
                                         projectionScale,
                                         &occupancy_,
                                         &clusterBounds_,
                                         &depthRange_,
                                         &clusterRanges_,
                                         &lightIndices_,
                                         gpuListCapacity_,
                                         assignment_->directionalCount};
    assignmentPass_->prepare(in);
    ResourceHandle counts =
        g.importBuffer("light_assign.counts", &assignmentPass_->clusterCounts());
    ResourceHandle usage = g.importBuffer("light_assign.usage", &assignmentPass_->usage(), true);
    ResourceHandle previous =
        g.importBuffer("light_assign.previous_masks", &assignmentPass_->previousMasks());
    auto readOccupancy = [&h](FrameGraph::PassBuilder& p) {
        p.read(h.lights, Use::StorageRead);
        p.read(h.tileMasks, Use::StorageRead);
        p.read(h.clusterBounds, Use::StorageRead);
        p.read(h.depthRange, Use::StorageRead);
    };
    {
        auto p = g.addPass("light_assign_count", PassKind::Device, [this, in](PassContext& ctx) {
            assignmentPass_->recordCount(ctx.cmd(), in);
        });
        readOccupancy(p);
        counts = p.write(counts, Use::StorageReadWrite);
    }
    {
        auto p = g.addPass("light_assign_allocate", PassKind::Device, [this, in](PassContext& ctx) {
            assignmentPass_->recordAllocate(ctx.cmd(), in);
        });
        p.read(h.tileMasks, Use::StorageRead);
        counts = p.write(counts, Use::StorageReadWrite);
        h.clusterRanges = p.write(h.clusterRanges, Use::StorageReadWrite);
        usage = p.write(usage, Use::StorageReadWrite);
        previous = p.write(previous, Use::StorageReadWrite);
    }
    {
        auto p = g.addPass("light_assign_write", PassKind::Device, [this, in](PassContext& ctx) {
            assignmentPass_->recordWrite(ctx.cmd(), in);
        });
        readOccupancy(p);
        p.read(h.clusterRanges, Use::StorageRead);
        counts = p.write(counts, Use::StorageReadWrite);
        h.lightIndices = p.write(h.lightIndices, Use::StorageReadWrite);
    }
    {
        auto p = g.addPass("light_assign_sort", PassKind::Device, [this, in](PassContext& ctx) {
            assignmentPass_->recordSort(ctx.cmd(), in);
        });
        p.read(h.tileMasks, Use::StorageRead);
        h.clusterRanges = p.write(h.clusterRanges, Use::StorageReadWrite);
        h.lightIndices = p.write(h.lightIndices, Use::StorageReadWrite);
        counts = p.write(counts, Use::StorageReadWrite);
    }
    gpuAssignTimed_ = true;
}

uint32_t Renderer::declareScene(const FrameInputs& inputs, SceneResources& resources,
                                uint32_t hdrId) {
    FrameGraph& g = *graph_;
    LightingFeatures features = featuresOf(inputs.scene, resources, options_);
    lightingPass_->setFeatures(features);
    // The environment BRDF LUT is the same for every sky: built once, when first needed.
    if (features.ibl && !brdfLut_) brdfLut_ = std::make_unique<EnvironmentBrdfLut>(context_);
    // The reference mode also samples the sky by luminance: a table per environment.
    if (features.ibl == IblMode::Reference &&
        (!samplingTable_ || samplingTable_->source() != resources.environment())) {
        samplingTable_ =
            std::make_unique<EnvironmentSamplingTable>(context_, *resources.environment());
    }
    features_ = features.names();
    // Blended draws leave the G-buffer for the forward pass; none, and it records nothing.
    const bool blended = transparentPass_->prepare(inputs.scene, resources, features);
    uploadFrameData(inputs);
    stats_.lights = lights_->count();
    stats_.lightsRewritten = lights_->rewrittenLastUpdate();
    stats_.lightAssignMs = 0.0;
    gpuAssignTimed_ = false;
    if (!depthRange_.handle()) {
        depthRange_ = GpuBuffer(
            context_, 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
            MemoryLocation::HostVisible);
    }
    if (!features.clustered) {
        // The brute-force variant never reads the lists; bind valid placeholders.
        ensureBuffer(context_, clusterRanges_, 16);
        ensureBuffer(context_, lightIndices_, 16);
        assignment_->directionalCount = 0;
    }

    SceneHandles h;
    h.hdr = {hdrId, 0};
    for (size_t i = 0; i < h.color.size(); ++i) {
        h.color[i] = g.createImage(GBufferTargets::kColorNames[i],
                                   GBufferTargets::colorDesc(i, width_, height_));
    }
    h.depth = g.createImage("gbuffer.depth", GBufferTargets::depthDesc(width_, height_));
    h.camera = g.importBuffer("camera", &cameraBuffer_);
    h.lights = g.importBuffer("lights", &lights_->buffer());
    h.depthRange = g.importBuffer("cluster.depth_range", &depthRange_);
    h.clusterRanges = g.importBuffer("cluster.ranges", &clusterRanges_);
    h.lightIndices = g.importBuffer("cluster.light_indices", &lightIndices_);
    const ResourceHandle pairCounts =
        g.importBuffer("lighting.pair_counts", &pairCounts_, features.countLightPairs);

    const SceneHandles ids = h;  // resource ids for the passes to look up
    auto gbufferViews = [ids](PassContext& ctx) {
        GBufferTargets targets;
        for (size_t i = 0; i < targets.color.size(); ++i)
            targets.color[i] = ctx.image(ids.color[i]);
        targets.depth = ctx.image(ids.depth);
        return targets;
    };
    {
        auto p = g.addPass("gbuffer", PassKind::Device,
                           [this, gbufferViews, ids, &inputs, &resources](PassContext& ctx) {
                               gbufferPass_->record(ctx.cmd(), gbufferViews(ctx),
                                                    ctx.image(ids.hdr), inputs.clearRadiance,
                                                    inputs.scene, resources, cameraBuffer_);
                           });
        p.read(h.camera, Use::Uniform, kRasterStages);
        for (ResourceHandle& c : h.color)
            c = p.write(c, Use::ColorAttachment);
        h.depth = p.write(h.depth, Use::DepthWrite);
        h.hdr = p.write(h.hdr, Use::ColorAttachment);
    }
    if (features.clustered) declareClusterAssignment(inputs, resources, h, blended);

    const EnvironmentDescriptors environment = environmentPlaceholders_->describe(
        features.ibl ? resources.environment() : nullptr, brdfLut_.get(),
        samplingTable_ && features.ibl == IblMode::Reference ? &samplingTable_->buffer() : nullptr);
    const float skyIntensity = inputs.scene.skyIntensity;
    {
        auto p = g.addPass("lighting", PassKind::Device,
                           [this, gbufferViews, ids, environment, skyIntensity](PassContext& ctx) {
                               const GBufferTargets targets = gbufferViews(ctx);
                               LightingPass::Inputs lighting{
                                   &targets,        ctx.image(ids.hdr),
                                   &cameraBuffer_,  &lights_->buffer(),
                                   &clusterRanges_, &lightIndices_,
                                   &pairCounts_,    &depthRange_,
                                   grid_.get(),     assignment_->directionalCount};
                               lighting.environment = &environment;
                               lighting.skyIntensity = skyIntensity;
                               lighting.referenceSamples = options_.referenceSamples;
                               lightingPass_->record(ctx.cmd(), lighting);
                           });
        for (ResourceHandle c : h.color)
            p.read(c, Use::Sampled);
        p.read(h.depth, Use::Sampled);
        p.read(h.camera, Use::Uniform);
        p.read(h.lights, Use::StorageRead);
        if (features.clustered) {
            p.read(h.clusterRanges, Use::StorageRead);
            p.read(h.lightIndices, Use::StorageRead);
            p.read(h.depthRange, Use::StorageRead);
        }
        if (features.countLightPairs) p.write(pairCounts, Use::StorageWrite);
        h.hdr = p.write(h.hdr, Use::StorageReadWrite);
    }
    if (blended) {
        auto p = g.addPass(
            "forward_transparent", PassKind::Device,
            [this, ids, environment, skyIntensity, &resources](PassContext& ctx) {
                transparentPass_->recordShading(
                    ctx.cmd(), resources,
                    {ctx.image(ids.hdr), ctx.image(ids.depth), &cameraBuffer_, &lights_->buffer(),
                     &clusterRanges_, &lightIndices_, &depthRange_, grid_.get(),
                     assignment_->directionalCount, &environment, skyIntensity});
            });
        p.read(h.depth, Use::DepthRead);
        p.read(h.camera, Use::Uniform, kRasterStages);
        p.read(h.lights, Use::StorageRead, kFragmentStage);
        if (features.clustered) {
            p.read(h.clusterRanges, Use::StorageRead, kFragmentStage);
            p.read(h.lightIndices, Use::StorageRead, kFragmentStage);
            p.read(h.depthRange, Use::StorageRead, kFragmentStage);
        }
        h.hdr = p.write(h.hdr, Use::ColorAttachment);
        features_.push_back("forward_transparency");
    }
    return h.hdr.version;
}

VkCommandBuffer Renderer::recordFrame(FrameSubmitter& submitter, const FrameInputs& inputs,
                                      SceneResources* resources) {
    VkCommandBuffer cmd = submitter.begin();
    const Clock::time_point start = Clock::now();
    FrameGraph& g = *graph_;
    g.clear();
    ResourceHandle hdr = g.importImage("hdr", &hdr_, kDiscardAfterCopies, kReadyToCopy);
    ResourceHandle ldr = g.importImage("ldr", &ldr_, kDiscardAfterCopies, kReadyToCopy);
    if (inputs.testTriangleRadiance || !resources) {
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
    }
    features_.push_back("tonemap_aces");
    const float exposure = exposureFromEv100(inputs.scene.camera.ev100);
    {
        auto p =
            g.addPass("tonemap", PassKind::Device, [this, hdr, ldr, exposure](PassContext& ctx) {
                tonemapPass_->record(ctx.cmd(), ctx.image(hdr), ctx.image(ldr), exposure);
            });
        p.read(hdr, Use::StorageRead);
        p.write(ldr, Use::StorageWrite);
    }
    stats_.graphRecordMs = millisecondsSince(start);
    executor_->execute(g, submitter, cmd);
    frameRecorded_ = true;
    const FrameGraphStats& graphStats = executor_->stats();
    stats_.graphCompileMs = graphStats.compileMs;
    stats_.graphReused = graphStats.reused;
    stats_.graphPasses = graphStats.passes;
    stats_.graphCulledPasses = graphStats.culledPasses;
    stats_.graphResources = graphStats.resources;
    stats_.graphBarriers = graphStats.barriers;
    stats_.transientBytes = graphStats.transientBytes;
    stats_.transientBytesUnaliased = graphStats.transientBytesUnaliased;
    return cmd;
}

std::string Renderer::frameGraphDot() const {
    return executor_->dot(*graph_);
}

const RendererStats& Renderer::collectStats() {
    stats_.lightingMs = 0.0;
    stats_.passMs.clear();
    if (!frameRecorded_) return stats_;
    if (gpuAssignTimed_) {
        absorbGpuListUsage();
        stats_.lightAssignMs = 0.0;
    }
    stats_.passMs = executor_->passTimes();
    for (const auto& [name, ms] : stats_.passMs) {
        if (name == "lighting") stats_.lightingMs = ms;
        if (gpuAssignTimed_ && name.starts_with("light_assign_")) stats_.lightAssignMs += ms;
    }
    stats_.lightEvaluations = 0;
    stats_.litPairs = 0;
    if (options_.countLightPairs && !features_.empty() && features_[0] != "test_triangle") {
        const auto* counts = static_cast<const uint32_t*>(pairCounts_.mapped());
        for (uint32_t g = 0; g < LightingPass::workgroupCount(width_, height_); ++g) {
            stats_.lightEvaluations += counts[2 * g];
            stats_.litPairs += counts[2 * g + 1];
        }
    }
    return stats_;
}

}  // namespace candela::render
