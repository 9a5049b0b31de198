#include "clustered/cluster_light_lists.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string>

#include "candela/ecs/job_system.h"
#include "candela/render/gpu_context.h"
#include "clustered/light_assignment.h"
#include "cpu_clock.h"
#include "frame_graph/frame_graph_executor.h"
#include "lights/gpu_light_types.h"
#include "passes/depth_occupancy/depth_occupancy_pass.h"
#include "passes/forward_transparent/forward_transparent_pass.h"
#include "passes/light_assignment/light_assignment_pass.h"

namespace candela::render {

namespace {

// List entries keep the light index in 28 bits (common/light_list_entry.h).
void checkLightIndexRange(size_t lightCount) {
    if (lightCount > size_t(LIGHT_ENTRY_INDEX_MASK) + 1) {
        throw std::length_error("clustered lighting: " + std::to_string(lightCount) +
                                " lights, over the 2^28 a light list entry can index");
    }
}

}  // namespace

bool ensureHostBuffer(GpuContext& context, GpuBuffer& buffer, VkDeviceSize bytes,
                      VkBufferUsageFlags extraUsage) {
    bytes = std::max<VkDeviceSize>(bytes, 16);
    if (buffer.handle() && buffer.size() >= bytes) return false;
    VkDeviceSize size = std::max(bytes, buffer.size() * 2);
    buffer = GpuBuffer(context, size, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | extraUsage,
                       MemoryLocation::HostVisible);
    return true;
}

ClusterLightLists::ClusterLightLists(GpuContext& context, const RendererOptions& options,
                                     LightAssignmentDevice device)
    : context_(context),
      options_(options),
      device_(device),
      grid_(std::make_unique<ClusterGrid>()),
      assignment_(std::make_unique<LightAssignment>()),
      jobs_(std::make_unique<ecs::JobSystem>()),
      occupancyPass_(std::make_unique<DepthOccupancyPass>(context)) {
    if (device_ == LightAssignmentDevice::Gpu) {
        assignmentPass_ = std::make_unique<LightAssignmentPass>(context);
    }
    depthRange_ = GpuBuffer(context, 16,
                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                            MemoryLocation::HostVisible);
}

ClusterLightLists::~ClusterLightLists() = default;

uint32_t ClusterLightLists::directionalCount() const {
    return assignment_->directionalCount;
}

void ClusterLightLists::setView(const CameraView& view, uint32_t width, uint32_t height) {
    // The cluster bounds are the largest buffer per cluster: tiles grow until it binds.
    const uint32_t tileSize = ClusterGrid::tileSizeFitting(
        options_.tileSize, options_.slices, width, height, CLUSTER_BOUNDS_FLOATS * sizeof(float),
        context_.properties().limits.maxStorageBufferRange);
    *grid_ = ClusterGrid::make(tileSize, options_.slices, width, height, view.projection[0][0],
                               view.projection[1][1], view.nearPlane, view.farPlane);
    projectionScale_ = {view.projection[0][0], view.projection[1][1]};
    width_ = width;
    height_ = height;
}

void ClusterLightLists::usePlaceholders() {
    // The brute-force variant never reads the lists; bind valid placeholders.
    ensureHostBuffer(context_, clusterRanges_, 16);
    ensureHostBuffer(context_, lightIndices_, 16);
    assignment_->directionalCount = 0;
    assignedOnDevice_ = false;
}

void ClusterLightLists::assignOnCpu(const FrameInputs& inputs, RendererStats& stats) {
    // The slicing the occupancy pass derived from the measured depth range, bit for bit.
    const auto* range = static_cast<const uint32_t*>(depthRange_.mapped());
    float sliceNear, logRatio;
    std::memcpy(&sliceNear, &range[2], sizeof(float));
    std::memcpy(&logRatio, &range[3], sizeof(float));
    grid_->setSlicing(sliceNear, logRatio);
    ClusterOccupancy occupancy;
    occupancy.tileMasks = {static_cast<const uint64_t*>(occupancy_.mapped()), grid_->tileCount()};
    occupancy.pixelBounds = {static_cast<const float*>(clusterBounds_.mapped()),
                             size_t(grid_->clusterCount()) * CLUSTER_BOUNDS_FLOATS};
    // Ranges are written in place, only for the clusters that changed (light_assignment.h): a
    // new buffer starts from zeros.
    if (ensureHostBuffer(context_, clusterRanges_, VkDeviceSize(grid_->clusterCount()) * 8)) {
        std::memset(clusterRanges_.mapped(), 0, clusterRanges_.size());
        assignment_->rangedClusters.clear();
    }
    assignLights(*grid_, inputs.scene.lights, inputs.scene.camera.view, occupancy, jobs_.get(),
                 {static_cast<uint32_t*>(clusterRanges_.mapped()), clusterRanges_.size() / 4},
                 *assignment_);
    // The lists are sized exactly each frame, so a light is never dropped; growing the buffer
    // is what the overflow counter reports.
    if (ensureHostBuffer(context_, lightIndices_,
                         assignment_->lightIndices.size() * sizeof(uint32_t)) &&
        !assignment_->lightIndices.empty()) {
        ++stats.lightListGrew;
    }
    // A frame without lights has no list entries, and memcpy from an empty vector's null
    // data() is undefined even for 0 bytes (UBSan).
    if (!assignment_->lightIndices.empty()) {
        std::memcpy(lightIndices_.mapped(), assignment_->lightIndices.data(),
                    assignment_->lightIndices.size() * sizeof(uint32_t));
    }
    stats.clusters = grid_->clusterCount();
    stats.clustersOccupied = assignment_->occupiedClusters;
    stats.lightClusterPairs = assignment_->assignedPairs;
}

void ClusterLightLists::prepareDeviceAssignment(const FrameInputs& inputs, RendererStats& stats) {
    absorbDeviceListUsage(stats);
    std::span<const LightInstance> lights = inputs.scene.lights;
    // Directional lights lead the index buffer, as on the CPU path; the device lists follow.
    std::vector<uint32_t>& directional = assignment_->lightIndices;
    directional.clear();
    for (uint32_t i = 0; i < lights.size(); ++i) {
        if (inEveryCluster(lights[i].light)) directional.push_back(i);
    }
    assignment_->directionalCount = uint32_t(directional.size());
    if (gpuListEntriesWanted_ == 0) {
        // First frame: a guess (the floor benchmark needs under 8 entries per light); later
        // frames grow from what the previous one asked for.
        gpuListEntriesWanted_ = options_.initialGpuLightListEntries
                                    ? options_.initialGpuLightListEntries
                                    : std::max<uint32_t>(uint32_t(lights.size()) * 16, 1u << 16);
    }
    ensureHostBuffer(context_, lightIndices_,
                     VkDeviceSize(std::max<size_t>(gpuListEntriesWanted_, directional.size())) * 4);
    if (!directional.empty()) {  // data() may be null (see assignOnCpu)
        std::memcpy(lightIndices_.mapped(), directional.data(),
                    directional.size() * sizeof(uint32_t));
    }
    ensureHostBuffer(context_, clusterRanges_, VkDeviceSize(grid_->clusterCount()) * 8);
    gpuListCapacity_ = uint32_t(lightIndices_.size() / 4);
    gpuListPending_ = true;
    stats.clusters = grid_->clusterCount();
}

void ClusterLightLists::absorbDeviceListUsage(RendererStats& stats) {
    // The frame that recorded the device assignment has completed (collectStats, or the next
    // frame after FrameSubmitter::begin waited for it).
    if (!gpuListPending_) return;
    gpuListPending_ = false;
    const uint32_t requested = assignmentPass_->requestedEntries();
    stats.lightClusterPairs = requested - assignment_->directionalCount;
    if (requested > gpuListCapacity_) {
        ++stats.lightListGrew;
        gpuListEntriesWanted_ = requested + requested / 4;
        // The clusters marked overflowed (count = ~0u, light_assignment_pass.h).
        const auto* ranges = static_cast<const uint32_t*>(clusterRanges_.mapped());
        for (uint32_t c = 0; c < grid_->clusterCount(); ++c) {
            stats.lightListOverflows += ranges[2 * c + 1] == ~0u ? 1u : 0u;
        }
    }
    stats.clustersOccupied = 0;
    const auto* masks = static_cast<const uint64_t*>(occupancy_.mapped());
    for (uint32_t t = 0; t < grid_->tileCount(); ++t) {
        stats.clustersOccupied += uint32_t(std::popcount(masks[t]));
    }
}

void ClusterLightLists::collectStats(RendererStats& stats) {
    if (assignedOnDevice_) absorbDeviceListUsage(stats);
}

ClusterLightLists::Lists ClusterLightLists::declare(FrameGraph& g, const Inputs& in,
                                                    RendererStats& stats) {
    const bool onDevice = device_ == LightAssignmentDevice::Gpu;
    assignedOnDevice_ = false;
    ensureOccupancyBuffers();
    checkLightIndexRange(in.frame->scene.lights.size());
    // Read on the CPU: by the host assignment pass, or (device path) for the stats.
    OccupancyHandles occupancy;
    occupancy.tileMasks = g.importBuffer("cluster.tile_masks", &occupancy_, onDevice);
    occupancy.clusterBounds = g.importBuffer("cluster.bounds", &clusterBounds_);
    Lists lists;
    lists.depthRange = g.importBuffer("cluster.depth_range", &depthRange_);
    // The device path's overflowed clusters are counted on the CPU after the frame.
    lists.ranges = g.importBuffer("cluster.ranges", &clusterRanges_, onDevice);
    lists.indices = g.importBuffer("cluster.light_indices", &lightIndices_);
    declareDepthOccupancy(g, in.depth, lists.depthRange, occupancy);
    if (in.blended) declareBlendedOccupancy(g, in, lists.depthRange, occupancy);
    if (!onDevice) {
        declareHostAssignment(g, in.frame, occupancy, lists, stats);
        return lists;
    }
    declareDeviceAssignment(g, in, occupancy, lists, stats);
    assignedOnDevice_ = true;
    return lists;
}

void ClusterLightLists::ensureOccupancyBuffers() {
    ensureHostBuffer(context_, occupancy_, VkDeviceSize(grid_->tileCount()) * 8);
    ensureHostBuffer(context_, clusterBounds_,
                     VkDeviceSize(grid_->clusterCount()) * CLUSTER_BOUNDS_FLOATS * sizeof(float));
}

void ClusterLightLists::declareDepthOccupancy(FrameGraph& g, ResourceHandle depth,
                                              ResourceHandle& depthRange,
                                              OccupancyHandles& occupancy) {
    const glm::vec2 projectionScale = projectionScale_;
    {
        auto p = g.addPass("depth_range_clear", PassKind::Device, [this](PassContext& ctx) {
            occupancyPass_->recordClearRange(ctx.cmd(), depthRange_);
        });
        depthRange = p.write(depthRange, Use::TransferDst);
    }
    {
        auto p = g.addPass("depth_range", PassKind::Device, [this, depth](PassContext& ctx) {
            occupancyPass_->recordMeasureRange(ctx.cmd(), ctx.image(depth), *grid_, depthRange_);
        });
        p.read(depth, Use::Sampled);
        depthRange = p.write(depthRange, Use::StorageReadWrite);
    }
    {
        auto p = g.addPass(
            "depth_occupancy", PassKind::Device, [this, depth, projectionScale](PassContext& ctx) {
                occupancyPass_->recordMarkOccupancy(ctx.cmd(), ctx.image(depth), *grid_,
                                                    projectionScale,
                                                    {&occupancy_, &clusterBounds_, &depthRange_});
            });
        p.read(depth, Use::Sampled);
        depthRange = p.write(depthRange, Use::StorageReadWrite);
        occupancy.tileMasks = p.write(occupancy.tileMasks, Use::StorageWrite);
        occupancy.clusterBounds = p.write(occupancy.clusterBounds, Use::StorageWrite);
    }
}

void ClusterLightLists::declareBlendedOccupancy(FrameGraph& g, const Inputs& in,
                                                ResourceHandle depthRange,
                                                OccupancyHandles& occupancy) {
    ForwardTransparentPass* blended = in.blended;
    SceneResources* resources = in.resources;
    const ResourceHandle depth = in.depth;
    const glm::vec2 projectionScale = projectionScale_;
    ResourceHandle bounds =
        g.createBuffer("transparent.bounds", ForwardTransparentPass::boundsBytes(*grid_),
                       VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    const GpuBuffer* camera = in.cameraBuffer;
    auto occupancyInputs = [this, depth, bounds, camera, projectionScale](PassContext& ctx) {
        return ForwardTransparentPass::OccupancyInputs{
            ctx.image(depth),   camera,      &depthRange_,   &occupancy_, &clusterBounds_,
            ctx.buffer(bounds), grid_.get(), projectionScale};
    };
    auto clear = g.addPass("transparent_bounds_clear", PassKind::Device,
                           [blended, occupancyInputs](PassContext& ctx) {
                               blended->recordClearBounds(ctx.cmd(), occupancyInputs(ctx));
                           });
    bounds = clear.write(bounds, Use::TransferDst);
    auto mark =
        g.addPass("transparent_occupancy", PassKind::Device,
                  [blended, resources, occupancyInputs](PassContext& ctx) {
                      blended->recordMarkOccupancy(ctx.cmd(), *resources, occupancyInputs(ctx));
                  });
    mark.read(depth, Use::Sampled, kFragmentStage);
    mark.read(in.camera, Use::Uniform, kRasterStages);
    mark.read(depthRange, Use::StorageRead, kFragmentStage);
    if (in.deformed.valid()) mark.read(in.deformed, Use::VertexInput);
    bounds = mark.write(bounds, Use::StorageReadWrite, kFragmentStage);
    auto merge = g.addPass("transparent_occupancy_merge", PassKind::Device,
                           [blended, occupancyInputs](PassContext& ctx) {
                               blended->recordMergeOccupancy(ctx.cmd(), occupancyInputs(ctx));
                           });
    merge.read(bounds, Use::StorageRead);
    occupancy.tileMasks = merge.write(occupancy.tileMasks, Use::StorageReadWrite);
    occupancy.clusterBounds = merge.write(occupancy.clusterBounds, Use::StorageReadWrite);
}

void ClusterLightLists::declareHostAssignment(FrameGraph& g, const FrameInputs* frame,
                                              const OccupancyHandles& occupancy, Lists& lists,
                                              RendererStats& stats) {
    // The frame splits here: the occupancy must be on the CPU before lights are assigned.
    auto p = g.addPass("light_assignment_cpu", PassKind::Host, [this, frame, &stats](PassContext&) {
        const CpuClock::time_point start = CpuClock::now();
        assignOnCpu(*frame, stats);
        stats.lightAssignMs = millisecondsSince(start);
    });
    p.read(occupancy.tileMasks, Use::HostRead);
    p.read(occupancy.clusterBounds, Use::HostRead);
    p.read(lists.depthRange, Use::HostRead);
    lists.ranges = p.write(lists.ranges, Use::HostWrite);
    lists.indices = p.write(lists.indices, Use::HostWrite);
}

void ClusterLightLists::declareDeviceAssignment(FrameGraph& g, const Inputs& in,
                                                const OccupancyHandles& occupancy, Lists& lists,
                                                RendererStats& stats) {
    prepareDeviceAssignment(*in.frame, stats);
    const LightAssignmentPass::Inputs assign{in.lightBuffer,
                                             in.lightCount,
                                             in.lightCapacity,
                                             in.frame->scene.camera.view,
                                             grid_.get(),
                                             width_,
                                             height_,
                                             projectionScale_,
                                             &occupancy_,
                                             &clusterBounds_,
                                             &depthRange_,
                                             &clusterRanges_,
                                             &lightIndices_,
                                             gpuListCapacity_,
                                             assignment_->directionalCount};
    assignmentPass_->prepare(assign);
    ResourceHandle counts =
        g.importBuffer("light_assign.counts", &assignmentPass_->clusterCounts());
    ResourceHandle usage = g.importBuffer("light_assign.usage", &assignmentPass_->usage(), true);
    ResourceHandle previous =
        g.importBuffer("light_assign.previous_masks", &assignmentPass_->previousMasks());
    auto readOccupancy = [&](FrameGraph::PassBuilder& p) {
        p.read(in.lights, Use::StorageRead);
        p.read(occupancy.tileMasks, Use::StorageRead);
        p.read(occupancy.clusterBounds, Use::StorageRead);
        p.read(lists.depthRange, Use::StorageRead);
    };
    LightAssignmentPass* pass = assignmentPass_.get();
    {
        auto p =
            g.addPass("light_assign_count", PassKind::Device,
                      [pass, assign](PassContext& ctx) { pass->recordCount(ctx.cmd(), assign); });
        readOccupancy(p);
        counts = p.write(counts, Use::StorageReadWrite);
    }
    {
        auto p = g.addPass(
            "light_assign_allocate", PassKind::Device,
            [pass, assign](PassContext& ctx) { pass->recordAllocate(ctx.cmd(), assign); });
        p.read(occupancy.tileMasks, Use::StorageRead);
        counts = p.write(counts, Use::StorageReadWrite);
        lists.ranges = p.write(lists.ranges, Use::StorageReadWrite);
        usage = p.write(usage, Use::StorageReadWrite);
        previous = p.write(previous, Use::StorageReadWrite);
    }
    {
        auto p =
            g.addPass("light_assign_write", PassKind::Device,
                      [pass, assign](PassContext& ctx) { pass->recordWrite(ctx.cmd(), assign); });
        readOccupancy(p);
        p.read(lists.ranges, Use::StorageRead);
        counts = p.write(counts, Use::StorageReadWrite);
        lists.indices = p.write(lists.indices, Use::StorageReadWrite);
    }
    {
        auto p = g.addPass("light_assign_sort", PassKind::Device, [pass, assign](PassContext& ctx) {
            pass->recordSort(ctx.cmd(), assign);
        });
        p.read(occupancy.tileMasks, Use::StorageRead);
        lists.ranges = p.write(lists.ranges, Use::StorageReadWrite);
        lists.indices = p.write(lists.indices, Use::StorageReadWrite);
        counts = p.write(counts, Use::StorageReadWrite);
    }
}

}  // namespace candela::render
