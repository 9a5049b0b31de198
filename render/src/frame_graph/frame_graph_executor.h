#pragma once
// Runs a declared FrameGraph on the device: compiles it (or reuses the compiled graph while
// the frame's shape is unchanged), creates the transient images and buffers in one aliased
// memory pool, then records every live pass in order with the barrier batch before it and a
// pair of timestamps around it. A host pass ends the command buffer, submits it, waits, runs
// on the CPU and begins the next one: the only place a frame splits its submission.
#include <vulkan/vulkan.h>

#include <string>
#include <utility>
#include <vector>

#include "candela/render/renderer_options.h"
#include "frame_graph/frame_graph.h"
#include "frame_graph/graph_resources.h"

namespace candela::render {

class FrameSubmitter;
class GpuContext;

class PassContext {
public:
    VkCommandBuffer cmd() const { return cmd_; }
    ImageRef image(ResourceHandle h) const;
    BufferRef buffer(ResourceHandle h) const;

private:
    friend class FrameGraphExecutor;
    PassContext(const class FrameGraphExecutor& executor, const FrameGraph& graph,
                VkCommandBuffer cmd)
        : executor_(executor), graph_(graph), cmd_(cmd) {}
    const FrameGraphExecutor& executor_;
    const FrameGraph& graph_;
    VkCommandBuffer cmd_;
};

class FrameGraphExecutor {
public:
    explicit FrameGraphExecutor(GpuContext& context);
    ~FrameGraphExecutor();
    FrameGraphExecutor(const FrameGraphExecutor&) = delete;
    FrameGraphExecutor& operator=(const FrameGraphExecutor&) = delete;

    // Records `graph` into `cmd` (which may be replaced at host passes). Throws FrameGraphError.
    void execute(FrameGraph& graph, FrameSubmitter& submitter, VkCommandBuffer& cmd);

    // Per live pass of the last executed frame: name and GPU milliseconds (host passes: CPU).
    // Call after that frame's submission completed.
    std::vector<std::pair<std::string, double>> passTimes();
    const FrameGraphSummary& stats() const { return stats_; }
    // The last executed frame's compiled graph (execution order, barriers).
    const CompiledFrameGraph& compiled() const { return compiled_; }
    std::string dot(const FrameGraph& graph) const { return frameGraphDot(graph, compiled_); }

private:
    friend class PassContext;
    void realize(FrameGraph& graph);
    void releaseTransients();
    void recordBarriers(VkCommandBuffer cmd, const FrameGraph& graph, const BarrierBatch& batch);

    GpuContext& context_;
    uint64_t shape_ = 0;
    bool compiledValid_ = false;
    CompiledFrameGraph compiled_;
    FrameGraphSummary stats_;
    // Transients of the compiled shape: per resource, image (+ view) or buffer.
    struct Transient {
        VkImage image = VK_NULL_HANDLE;
        VkImageView view = VK_NULL_HANDLE;
        VkBuffer buffer = VK_NULL_HANDLE;
    };
    std::vector<Transient> transients_;
    VkDeviceMemory pool_ = VK_NULL_HANDLE;
    VkQueryPool timestamps_ = VK_NULL_HANDLE;
    uint32_t timestampCapacity_ = 0;
    std::vector<std::string> timedNames_;  // names of the last frame's live passes
    std::vector<double> hostMs_;           // CPU time of host passes (NaN for device passes)
    bool timestampsPending_ = false;
};

}  // namespace candela::render
