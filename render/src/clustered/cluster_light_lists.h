#pragma once
// The per-cluster light lists of a frame and everything that builds them: the cluster grid and
// buffers, the depth occupancy passes, the clusters blended surfaces mark, and light
// assignment, on the CPU job system (a host pass: the frame splits its submission there) or in
// compute shaders. declare() adds these passes to the frame graph; the lighting and forward
// passes then read ranges(), indices() and depthRange() through the handles it returns.
#include <glm/glm.hpp>

#include <memory>

#include "candela/render/frame_inputs.h"
#include "candela/render/gpu_buffer.h"
#include "candela/render/renderer_options.h"
#include "clustered/cluster_grid.h"
#include "frame_graph/frame_graph.h"

namespace candela::ecs {
class JobSystem;
}

namespace candela::render {

class DepthOccupancyPass;
class ForwardTransparentPass;
class GpuContext;
class LightAssignmentPass;
class SceneResources;
struct LightAssignment;

class ClusterLightLists {
public:
    ClusterLightLists(GpuContext& context, const RendererOptions& options,
                      LightAssignmentDevice device);
    ~ClusterLightLists();
    ClusterLightLists(const ClusterLightLists&) = delete;
    ClusterLightLists& operator=(const ClusterLightLists&) = delete;

    // The grid for this frame's camera and size (before declare()).
    void setView(const CameraView& view, uint32_t width, uint32_t height);
    const ClusterGrid& grid() const { return *grid_; }

    struct Inputs {
        const FrameInputs* frame;
        ResourceHandle depth;   // the G-buffer depth, written
        ResourceHandle camera;  // uniform buffer
        ResourceHandle lights;  // GpuLightBuffer's streams
        const GpuBuffer* cameraBuffer;
        const GpuBuffer* lightBuffer;
        uint32_t lightCount;
        uint32_t lightCapacity;
        ForwardTransparentPass* blended;  // non-null: blended draws mark their clusters too
        SceneResources* resources;        // what the blended draws refer to
        ResourceHandle deformed;          // animated draws' vertices (invalid: none)
    };
    struct Lists {
        ResourceHandle ranges;      // offset, count per cluster
        ResourceHandle indices;     // light indices, directional lights first
        ResourceHandle depthRange;  // the slicing the lists were built for
    };
    // Declares occupancy, the blended surfaces' marks and assignment; `stats` receives the
    // clusters, pairs and assignment time as they are known.
    Lists declare(FrameGraph& graph, const Inputs& inputs, RendererStats& stats);
    // Brute-force frames: valid placeholder buffers, no passes.
    void usePlaceholders();

    const GpuBuffer& ranges() const { return clusterRanges_; }
    const GpuBuffer& indices() const { return lightIndices_; }
    const GpuBuffer& depthRange() const { return depthRange_; }
    uint32_t directionalCount() const;

    // After the frame completed: the device path's list usage and occupied clusters.
    void collectStats(RendererStats& stats);
    bool assignedOnDevice() const { return assignedOnDevice_; }

private:
    // The occupancy buffers' handles, as each pass of declare() leaves them.
    struct OccupancyHandles {
        ResourceHandle tileMasks;
        ResourceHandle clusterBounds;
    };

    // declare()'s steps, in order: the buffers the occupancy passes write, the depth range and
    // occupancy passes, the blended surfaces' marks (when there are any), then assignment on
    // the host or on the device. Each advances the handles it writes.
    void ensureOccupancyBuffers();
    void declareDepthOccupancy(FrameGraph& graph, ResourceHandle depth, ResourceHandle& depthRange,
                               OccupancyHandles& occupancy);
    void declareBlendedOccupancy(FrameGraph& graph, const Inputs& inputs, ResourceHandle depthRange,
                                 OccupancyHandles& occupancy);
    void declareHostAssignment(FrameGraph& graph, const FrameInputs* frame,
                               const OccupancyHandles& occupancy, Lists& lists,
                               RendererStats& stats);
    void declareDeviceAssignment(FrameGraph& graph, const Inputs& inputs,
                                 const OccupancyHandles& occupancy, Lists& lists,
                                 RendererStats& stats);
    void assignOnCpu(const FrameInputs& inputs, RendererStats& stats);
    void prepareDeviceAssignment(const FrameInputs& inputs, RendererStats& stats);
    void absorbDeviceListUsage(RendererStats& stats);

    GpuContext& context_;
    const RendererOptions& options_;
    LightAssignmentDevice device_;
    std::unique_ptr<ClusterGrid> grid_;
    std::unique_ptr<LightAssignment> assignment_;
    std::unique_ptr<ecs::JobSystem> jobs_;
    std::unique_ptr<DepthOccupancyPass> occupancyPass_;
    std::unique_ptr<LightAssignmentPass> assignmentPass_;  // device assignment only
    GpuBuffer occupancy_;      // uvec2 per tile, written by the GPU, read by the CPU
    GpuBuffer clusterBounds_;  // view-space box of each occupied cluster, then of its quarters
    GpuBuffer depthRange_;     // measured depth range and the slicing derived from it
    GpuBuffer clusterRanges_;  // offset, count per cluster
    GpuBuffer lightIndices_;
    glm::vec2 projectionScale_{1.0f};
    uint32_t width_ = 0;  // of the frame, in pixels
    uint32_t height_ = 0;
    bool assignedOnDevice_ = false;      // this frame assigned lights on the device
    bool gpuListPending_ = false;        // its list usage is not read back yet
    uint32_t gpuListCapacity_ = 0;       // index entries the device lists had this frame
    uint32_t gpuListEntriesWanted_ = 0;  // what the next frame allocates
};

// Host-visible storage buffer of at least `bytes` (and `extraUsage`); grows by doubling. True
// when it grew.
bool ensureHostBuffer(GpuContext& context, GpuBuffer& buffer, VkDeviceSize bytes,
                      VkBufferUsageFlags extraUsage = 0);

}  // namespace candela::render
