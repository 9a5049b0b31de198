#include "frame_graph/frame_graph_executor.h"

#include <cmath>
#include <limits>

#include "candela/render/frame_submitter.h"
#include "candela/render/gpu_context.h"
#include "cpu_clock.h"
#include "vk/image_creation.h"
#include "vk/vk_check.h"

namespace candela::render {

ImageRef PassContext::image(ResourceHandle h) const {
    const ResourceDecl& r = graph_.resources()[h.id];
    if (r.imported) return r.importedImage ? ImageRef(*r.importedImage) : ImageRef();
    const auto& t = executor_.transients_[h.id];
    return {t.image, t.view, r.imageDesc};
}

BufferRef PassContext::buffer(ResourceHandle h) const {
    const ResourceDecl& r = graph_.resources()[h.id];
    if (r.imported) return r.importedBuffer ? BufferRef(*r.importedBuffer) : BufferRef();
    return {executor_.transients_[h.id].buffer, r.bufferSize};
}

FrameGraphExecutor::FrameGraphExecutor(GpuContext& context) : context_(context) {}

FrameGraphExecutor::~FrameGraphExecutor() {
    releaseTransients();
    if (timestamps_) vkDestroyQueryPool(context_.device(), timestamps_, nullptr);
}

void FrameGraphExecutor::releaseTransients() {
    VkDevice device = context_.device();
    for (Transient& t : transients_) {
        if (t.view) vkDestroyImageView(device, t.view, nullptr);
        if (t.image) vkDestroyImage(device, t.image, nullptr);
        if (t.buffer) vkDestroyBuffer(device, t.buffer, nullptr);
    }
    transients_.clear();
    if (pool_) vkFreeMemory(device, pool_, nullptr);
    pool_ = VK_NULL_HANDLE;
}

void FrameGraphExecutor::realize(FrameGraph& graph) {
    // The previous frame may still read the old transients (one frame in flight): the caller's
    // FrameSubmitter::begin waited for it before this frame began recording.
    releaseTransients();
    VkDevice device = context_.device();
    auto resources = graph.resources();
    transients_.assign(resources.size(), {});
    for (size_t i = 0; i < resources.size(); ++i) {
        ResourceDecl& r = resources[i];
        if (r.imported) continue;
        Transient& t = transients_[i];
        VkMemoryRequirements requirements{};
        if (r.image) {
            t.image = createImage(device, r.imageDesc);
            vkGetImageMemoryRequirements(device, t.image, &requirements);
        } else {
            VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
            info.size = r.bufferSize;
            info.usage = r.bufferUsage;
            CANDELA_VK_CHECK(vkCreateBuffer(device, &info, nullptr, &t.buffer));
            vkGetBufferMemoryRequirements(device, t.buffer, &requirements);
        }
        // Images and buffers in one pool: keep them a granularity apart.
        const VkDeviceSize granularity = context_.properties().limits.bufferImageGranularity;
        r.needs = {requirements.size, std::max(requirements.alignment, granularity),
                   requirements.memoryTypeBits};
    }
    compiled_ = compileFrameGraph(graph);
    if (compiled_.poolBytes > 0) {
        VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        alloc.allocationSize = compiled_.poolBytes;
        alloc.memoryTypeIndex = context_.findMemoryType(compiled_.poolMemoryTypeBits,
                                                        VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
        CANDELA_VK_CHECK(vkAllocateMemory(device, &alloc, nullptr, &pool_));
    }
    for (size_t i = 0; i < resources.size(); ++i) {
        const ResourceDecl& r = resources[i];
        Transient& t = transients_[i];
        if (r.imported) continue;
        if (compiled_.lifetimes[i].first < 0) continue;  // culled: never bound, never used
        if (r.image) {
            CANDELA_VK_CHECK(vkBindImageMemory(device, t.image, pool_, compiled_.poolOffset[i]));
            t.view = createWholeView(device, t.image, r.imageDesc);
        } else {
            CANDELA_VK_CHECK(vkBindBufferMemory(device, t.buffer, pool_, compiled_.poolOffset[i]));
        }
    }
}

void FrameGraphExecutor::recordBarriers(VkCommandBuffer cmd, const FrameGraph& graph,
                                        const BarrierBatch& batch) {
    if (batch.empty()) return;
    VkMemoryBarrier2 memory{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    memory.srcStageMask = batch.memorySrcStages;
    memory.srcAccessMask = batch.memorySrcAccess;
    memory.dstStageMask = batch.memoryDstStages;
    memory.dstAccessMask = batch.memoryDstAccess;
    std::vector<VkImageMemoryBarrier2> images;
    images.reserve(batch.images.size());
    const PassContext lookup(*this, graph, cmd);
    for (const ImageBarrier& b : batch.images) {
        const ImageRef image = lookup.image({b.resource, 0});
        VkImageMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
        barrier.srcStageMask = b.srcStages;
        barrier.srcAccessMask = b.srcAccess;
        barrier.dstStageMask = b.dstStages;
        barrier.dstAccessMask = b.dstAccess;
        barrier.oldLayout = b.oldLayout;
        barrier.newLayout = b.newLayout;
        barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        barrier.image = image.handle();
        const ImageDesc& desc = image.desc();
        barrier.subresourceRange = {aspectOf(desc.format), 0, desc.mipLevels, 0,
                                    desc.cube ? 6u : 1u};
        images.push_back(barrier);
    }
    VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.memoryBarrierCount = batch.hasMemoryBarrier() ? 1 : 0;
    dependency.pMemoryBarriers = &memory;
    dependency.imageMemoryBarrierCount = uint32_t(images.size());
    dependency.pImageMemoryBarriers = images.data();
    vkCmdPipelineBarrier2(cmd, &dependency);
}

void FrameGraphExecutor::execute(FrameGraph& graph, FrameSubmitter& submitter,
                                 VkCommandBuffer& cmd) {
    const uint64_t shape = graph.shapeHash();
    stats_.reused = compiledValid_ && shape == shape_;
    stats_.compileMs = 0.0;
    if (!stats_.reused) {
        const CpuClock::time_point start = CpuClock::now();
        compiledValid_ = false;
        realize(graph);
        compiledValid_ = true;
        shape_ = shape;
        stats_.compileMs = millisecondsSince(start);
    }
    stats_.passes = uint32_t(compiled_.order.size());
    stats_.culledPasses = uint32_t(graph.passes().size() - compiled_.order.size());
    stats_.resources = uint32_t(graph.resources().size());
    stats_.barriers = uint32_t(compiled_.barrierCount);
    stats_.transientBytes = compiled_.poolBytes;
    stats_.transientBytesUnaliased = compiled_.unaliasedBytes;

    const uint32_t queries = uint32_t(compiled_.order.size()) * 2;
    if (queries > timestampCapacity_) {
        if (timestamps_) vkDestroyQueryPool(context_.device(), timestamps_, nullptr);
        VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
        info.queryType = VK_QUERY_TYPE_TIMESTAMP;
        info.queryCount = queries;
        CANDELA_VK_CHECK(vkCreateQueryPool(context_.device(), &info, nullptr, &timestamps_));
        timestampCapacity_ = queries;
    }
    if (queries) vkCmdResetQueryPool(cmd, timestamps_, 0, queries);
    timedNames_.clear();
    hostMs_.assign(compiled_.order.size(), std::numeric_limits<double>::quiet_NaN());

    auto passes = graph.passes();
    for (size_t i = 0; i < compiled_.order.size(); ++i) {
        PassDecl& pass = passes[compiled_.order[i]];
        timedNames_.push_back(pass.name);
        recordBarriers(cmd, graph, compiled_.before[i]);
        if (pass.kind == PassKind::Host) {
            submitter.submit();
            submitter.waitIdle();
            const CpuClock::time_point start = CpuClock::now();
            PassContext context(*this, graph, VK_NULL_HANDLE);
            if (pass.execute) pass.execute(context);
            hostMs_[i] = millisecondsSince(start);
            cmd = submitter.begin();
            continue;
        }
        vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT, timestamps_,
                             uint32_t(2 * i));
        PassContext context(*this, graph, cmd);
        if (pass.execute) pass.execute(context);
        vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT, timestamps_,
                             uint32_t(2 * i + 1));
    }
    recordBarriers(cmd, graph, compiled_.atEnd);
    timestampsPending_ = queries > 0;
}

std::vector<std::pair<std::string, double>> FrameGraphExecutor::passTimes() {
    std::vector<std::pair<std::string, double>> times;
    if (!timestampsPending_) return times;
    std::vector<uint64_t> ticks(2 * timedNames_.size(), 0);
    const double period = context_.properties().limits.timestampPeriod * 1e-6;
    for (size_t i = 0; i < timedNames_.size(); ++i) {
        if (!std::isnan(hostMs_[i])) {
            times.emplace_back(timedNames_[i], hostMs_[i]);
            continue;
        }
        uint64_t pair[2] = {0, 0};
        const VkResult result =
            vkGetQueryPoolResults(context_.device(), timestamps_, uint32_t(2 * i), 2, sizeof(pair),
                                  pair, sizeof(uint64_t), VK_QUERY_RESULT_64_BIT);
        times.emplace_back(timedNames_[i],
                           result == VK_SUCCESS ? double(pair[1] - pair[0]) * period : 0.0);
    }
    return times;
}

}  // namespace candela::render
