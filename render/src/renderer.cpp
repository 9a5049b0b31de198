#include "candela/render/renderer.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstring>

#include "candela/ecs/job_system.h"
#include "candela/render/frame_submitter.h"
#include "candela/render/gpu_context.h"
#include "candela/render/scene_resources.h"
#include "clustered/cluster_grid.h"
#include "clustered/light_assignment.h"
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
#include "vk/memory_barrier.h"
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

void computeToHostBarrier(VkCommandBuffer cmd) {
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
}

}  // namespace

Renderer::Renderer(GpuContext& context, uint32_t width, uint32_t height,
                   const RendererOptions& options)
    : context_(context),
      options_(options),
      width_(width),
      height_(height),
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
    if (options_.lightAssignment == LightAssignmentDevice::Gpu) {
        assignmentPass_ = std::make_unique<LightAssignmentPass>(context_);
    }
    VkQueryPoolCreateInfo queryInfo{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    queryInfo.queryType = VK_QUERY_TYPE_TIMESTAMP;
    queryInfo.queryCount = 4;  // lighting begin/end, device assignment begin/end
    CANDELA_VK_CHECK(vkCreateQueryPool(context.device(), &queryInfo, nullptr, &timestamps_));
}

Renderer::~Renderer() {
    brdfLut_.reset();
    samplingTable_.reset();
    vkDestroyQueryPool(context_.device(), timestamps_, nullptr);
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
    gbuffer_ = std::make_unique<GBufferTargets>(context_, width_, height_);
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

void Renderer::recordGpuAssignment(VkCommandBuffer cmd, const FrameInputs& inputs) {
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

    vkCmdResetQueryPool(cmd, timestamps_, 2, 2);
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, timestamps_, 2);
    const glm::mat4& projection = inputs.scene.camera.projection;
    LightAssignmentPass::Inputs in{&lights_->buffer(),
                                   lights_->count(),
                                   lights_->capacity(),
                                   inputs.scene.camera.view,
                                   grid_.get(),
                                   width_,
                                   height_,
                                   {projection[0][0], projection[1][1]},
                                   &occupancy_,
                                   &clusterBounds_,
                                   &depthRange_,
                                   &clusterRanges_,
                                   &lightIndices_,
                                   gpuListCapacity_,
                                   assignment_->directionalCount};
    assignmentPass_->record(cmd, in);
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, timestamps_, 3);
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

void Renderer::recordScene(FrameSubmitter& submitter, VkCommandBuffer& cmd,
                           const FrameInputs& inputs, SceneResources& resources) {
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

    for (const GpuImage& image : gbuffer_->color) {
        transitionImage(cmd, image, VK_IMAGE_LAYOUT_UNDEFINED,
                        VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                        VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, 0,
                        VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                        VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    }
    transitionImage(
        cmd, gbuffer_->depth, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
        VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, 0,
        VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
        VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
            VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT);
    gbufferPass_->record(cmd, *gbuffer_, hdr_, inputs.clearRadiance, inputs.scene, resources,
                         cameraBuffer_);

    for (const GpuImage& image : gbuffer_->color) {
        transitionImage(
            cmd, image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
            VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
            VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    }
    transitionImage(cmd, gbuffer_->depth, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                    VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    transitionImage(cmd, hdr_, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
                    VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                    VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                    VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);

    stats_.lightAssignMs = 0.0;
    gpuAssignTimed_ = false;
    if (!depthRange_.handle()) {
        depthRange_ = GpuBuffer(
            context_, 16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
            MemoryLocation::HostVisible);
    }
    if (features.clustered) {
        ensureBuffer(context_, occupancy_, VkDeviceSize(grid_->tileCount()) * 8);
        ensureBuffer(context_, clusterBounds_, VkDeviceSize(grid_->clusterCount()) * 24);
        const glm::mat4& projection = inputs.scene.camera.projection;
        occupancyPass_->record(cmd, gbuffer_->depth, *grid_, {projection[0][0], projection[1][1]},
                               {&occupancy_, &clusterBounds_, &depthRange_});
        if (blended) {
            transparentPass_->recordOccupancy(cmd, resources,
                                              {&gbuffer_->depth,
                                               &cameraBuffer_,
                                               &depthRange_,
                                               &occupancy_,
                                               &clusterBounds_,
                                               grid_.get(),
                                               {projection[0][0], projection[1][1]}});
        }
    }
    if (features.clustered && assignmentPass_) {
        memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                      VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                      VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
        recordGpuAssignment(cmd, inputs);
        gpuAssignTimed_ = true;
    } else if (features.clustered) {
        // Geometry first: the occupancy masks must be on the CPU before lights are assigned.
        computeToHostBarrier(cmd);
        submitter.submit();
        submitter.waitIdle();
        Clock::time_point start = Clock::now();
        assignLightsToClusters(inputs);
        stats_.lightAssignMs =
            std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        cmd = submitter.begin();
    } else {
        // The brute-force variant never reads the lists; bind valid placeholders.
        ensureBuffer(context_, clusterRanges_, 16);
        ensureBuffer(context_, lightIndices_, 16);
        assignment_->directionalCount = 0;
    }

    vkCmdResetQueryPool(cmd, timestamps_, 0, 2);
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, timestamps_, 0);
    LightingPass::Inputs lighting{gbuffer_.get(),  &hdr_,
                                  &cameraBuffer_,  &lights_->buffer(),
                                  &clusterRanges_, &lightIndices_,
                                  &pairCounts_,    &depthRange_,
                                  grid_.get(),     assignment_->directionalCount};
    const EnvironmentDescriptors environment = environmentPlaceholders_->describe(
        features.ibl ? resources.environment() : nullptr, brdfLut_.get(),
        samplingTable_ && features.ibl == IblMode::Reference ? &samplingTable_->buffer() : nullptr);
    lighting.environment = &environment;
    lighting.skyIntensity = inputs.scene.skyIntensity;
    lighting.referenceSamples = options_.referenceSamples;
    lightingPass_->record(cmd, lighting);
    vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, timestamps_, 1);
    timestampsWritten_ = true;
    if (features.countLightPairs) computeToHostBarrier(cmd);
    if (blended) {
        transparentPass_->recordShading(
            cmd, resources,
            {&hdr_, &gbuffer_->depth, &cameraBuffer_, &lights_->buffer(), &clusterRanges_,
             &lightIndices_, &depthRange_, grid_.get(), assignment_->directionalCount, &environment,
             inputs.scene.skyIntensity});
        features_.push_back("forward_transparency");
    }
}

void Renderer::recordTonemap(VkCommandBuffer cmd, float ev100) {
    transitionImage(cmd, ldr_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL,
                    VK_PIPELINE_STAGE_2_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                    VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
    tonemapPass_->record(cmd, hdr_, ldr_, exposureFromEv100(ev100));

    transitionImage(cmd, hdr_, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT,
                    VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
    transitionImage(cmd, ldr_, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                    VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
}

VkCommandBuffer Renderer::recordFrame(FrameSubmitter& submitter, const FrameInputs& inputs,
                                      SceneResources* resources) {
    VkCommandBuffer cmd = submitter.begin();
    timestampsWritten_ = false;
    transitionImage(cmd, hdr_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                    VK_PIPELINE_STAGE_2_TRANSFER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, 0,
                    VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                    VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    if (inputs.testTriangleRadiance || !resources) {
        trianglePass_->record(cmd, hdr_, inputs.clearRadiance,
                              inputs.testTriangleRadiance.value_or(inputs.clearRadiance));
        features_ = {"test_triangle"};
        transitionImage(
            cmd, hdr_, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_GENERAL,
            VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
            VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
    } else {
        recordScene(submitter, cmd, inputs, *resources);
    }
    features_.push_back("tonemap_aces");
    recordTonemap(cmd, inputs.scene.camera.ev100);
    return cmd;
}

const RendererStats& Renderer::collectStats() {
    stats_.lightingMs = 0.0;
    if (gpuAssignTimed_) {
        absorbGpuListUsage();
        uint64_t ticks[2] = {0, 0};
        if (vkGetQueryPoolResults(context_.device(), timestamps_, 2, 2, sizeof(ticks), ticks,
                                  sizeof(uint64_t), VK_QUERY_RESULT_64_BIT) == VK_SUCCESS) {
            stats_.lightAssignMs =
                double(ticks[1] - ticks[0]) * context_.properties().limits.timestampPeriod * 1e-6;
        }
    }
    if (timestampsWritten_) {
        uint64_t ticks[2] = {0, 0};
        if (vkGetQueryPoolResults(context_.device(), timestamps_, 0, 2, sizeof(ticks), ticks,
                                  sizeof(uint64_t), VK_QUERY_RESULT_64_BIT) == VK_SUCCESS) {
            stats_.lightingMs =
                double(ticks[1] - ticks[0]) * context_.properties().limits.timestampPeriod * 1e-6;
        }
    }
    stats_.lightEvaluations = 0;
    stats_.litPairs = 0;
    if (options_.countLightPairs && timestampsWritten_) {
        const auto* counts = static_cast<const uint32_t*>(pairCounts_.mapped());
        for (uint32_t g = 0; g < LightingPass::workgroupCount(width_, height_); ++g) {
            stats_.lightEvaluations += counts[2 * g];
            stats_.litPairs += counts[2 * g + 1];
        }
    }
    return stats_;
}

}  // namespace candela::render
