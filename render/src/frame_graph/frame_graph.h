#pragma once
// A frame as a graph: passes declare the images and buffers they create, read and write and
// how (resource_use.h); compile() orders them, culls the ones whose results nobody reads,
// derives each resource's lifetime, places transient resources in one memory pool (aliasing
// those whose lifetimes do not overlap) and computes every barrier and layout transition,
// batched per pass. Compiling needs no device: the compile-only tests run it without a GPU.
// The Vulkan side (frame_graph_executor.h) creates the transients and records the passes.
//
// Resources are versioned: writing version v of a resource yields a handle to version v + 1,
// and a pass that reads version v runs after the pass that wrote it and before the pass that
// writes v + 1. Two passes writing the same version have no defined order: an error.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <functional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "candela/render/gpu_image.h"
#include "frame_graph/resource_use.h"

namespace candela::render {

class GpuBuffer;
class PassContext;

struct FrameGraphError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct ResourceHandle {
    uint32_t id = UINT32_MAX;
    uint32_t version = 0;
    bool valid() const { return id != UINT32_MAX; }
};

enum class PassKind : uint8_t {
    Device,  // records commands into the frame's command buffer
    Host,    // runs on the CPU between two submissions (the frame splits there)
};

// The state an imported image is in before the frame, and the one it must be left in.
struct ImageState {
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;  // UNDEFINED: contents discarded
    VkPipelineStageFlags2 stages = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 access = 0;
};

// Memory a transient resource needs (vkGet*MemoryRequirements), filled in before compiling.
struct MemoryNeeds {
    VkDeviceSize size = 0;
    VkDeviceSize alignment = 1;
    uint32_t memoryTypeBits = ~0u;
};

struct ResourceDecl {
    std::string name;
    bool image = true;
    bool imported = false;
    ImageDesc imageDesc;  // images
    VkDeviceSize bufferSize = 0;
    VkBufferUsageFlags bufferUsage = 0;
    const GpuImage* importedImage = nullptr;
    const GpuBuffer* importedBuffer = nullptr;
    ImageState initial;  // imported images
    ImageState final;    // imported images: left in this state (layout UNDEFINED: as is)
    MemoryNeeds needs;   // transients
    bool hostReadsAfterFrame = false;  // imported buffers: read on the CPU once the frame ends
};

struct UseDecl {
    uint32_t resource = 0;
    uint32_t version = 0;  // the version read (writes produce version + 1)
    Use use = Use::Sampled;
    VkPipelineStageFlags2 shaderStages = kComputeStage;
};

struct PassDecl {
    std::string name;
    PassKind kind = PassKind::Device;
    bool sideEffect = false;  // never culled (it writes something outside the graph)
    std::vector<UseDecl> uses;
    std::function<void(PassContext&)> execute;
};

class FrameGraph {
public:
    class PassBuilder {
    public:
        void read(ResourceHandle h, Use use, VkPipelineStageFlags2 stages = kComputeStage);
        // Returns the handle to the version this write produces.
        ResourceHandle write(ResourceHandle h, Use use,
                             VkPipelineStageFlags2 stages = kComputeStage);
        void sideEffect();

    private:
        friend class FrameGraph;
        PassBuilder(FrameGraph& graph, uint32_t pass) : graph_(graph), pass_(pass) {}
        FrameGraph& graph_;
        uint32_t pass_;
    };

    ResourceHandle importImage(std::string name, const GpuImage* image, ImageState initial,
                               ImageState final);
    ResourceHandle importBuffer(std::string name, const GpuBuffer* buffer,
                                bool hostReadsAfterFrame = false);
    ResourceHandle createImage(std::string name, const ImageDesc& desc);
    ResourceHandle createBuffer(std::string name, VkDeviceSize size, VkBufferUsageFlags usage);

    // `setup` declares the pass's uses through the builder; `execute` records it.
    PassBuilder addPass(std::string name, PassKind kind, std::function<void(PassContext&)> execute);

    void clear();
    std::span<const ResourceDecl> resources() const { return resources_; }
    std::span<ResourceDecl> resources() { return resources_; }
    std::span<const PassDecl> passes() const { return passes_; }
    std::span<PassDecl> passes() { return passes_; }

    // A value that changes whenever the passes, their uses or the transient descriptions do:
    // a compiled graph stays valid while it is unchanged (imported handles may differ).
    uint64_t shapeHash() const;

private:
    std::vector<ResourceDecl> resources_;
    std::vector<PassDecl> passes_;
};

struct ImageBarrier {
    uint32_t resource = 0;
    VkImageLayout oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkImageLayout newLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkPipelineStageFlags2 srcStages = 0;
    VkAccessFlags2 srcAccess = 0;
    VkPipelineStageFlags2 dstStages = 0;
    VkAccessFlags2 dstAccess = 0;
};

// What to record before a pass (or at the end of the frame): one dependency with at most one
// global memory barrier (buffers, and images that keep their layout) and the image barriers.
struct BarrierBatch {
    VkPipelineStageFlags2 memorySrcStages = 0;
    VkAccessFlags2 memorySrcAccess = 0;
    VkPipelineStageFlags2 memoryDstStages = 0;
    VkAccessFlags2 memoryDstAccess = 0;
    std::vector<ImageBarrier> images;

    bool hasMemoryBarrier() const { return memorySrcStages || memoryDstStages; }
    bool empty() const { return !hasMemoryBarrier() && images.empty(); }
    size_t count() const { return images.size() + (hasMemoryBarrier() ? 1 : 0); }
};

struct ResourceLifetime {
    int32_t first = -1;  // position in CompiledFrameGraph::order; -1: unused
    int32_t last = -1;
};

struct CompiledFrameGraph {
    std::vector<uint32_t> order;       // live passes, in execution order (declaration indices)
    std::vector<bool> culled;          // per declared pass
    std::vector<BarrierBatch> before;  // per position in order
    BarrierBatch atEnd;  // imported images to their final state, host reads after the frame
    std::vector<ResourceLifetime> lifetimes;  // per resource
    // Transient placement: offset in the pool per resource (imported: unused), the pool's
    // size with aliasing and the sum of the transients' sizes without.
    std::vector<VkDeviceSize> poolOffset;
    std::vector<VkDeviceSize> poolSize;  // per resource: bytes a transient takes in the pool
    VkDeviceSize poolBytes = 0;
    VkDeviceSize unaliasedBytes = 0;
    uint32_t poolMemoryTypeBits = ~0u;
    size_t barrierCount = 0;  // image barriers + memory barriers
};

// Throws FrameGraphError naming the passes for a cycle, a read of a version nobody writes, or
// two writers of one version.
CompiledFrameGraph compileFrameGraph(const FrameGraph& graph);

// Graphviz of the compiled graph: passes (culled ones dashed, with their barrier counts),
// resources, and read/write edges labelled with the use.
std::string frameGraphDot(const FrameGraph& graph, const CompiledFrameGraph& compiled);

}  // namespace candela::render
