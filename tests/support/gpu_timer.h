#pragma once
// GPU milliseconds of the commands a callback records, from two timestamps around them in a
// one-shot submission (GpuContext::submitAndWait). For benchmarks and the report.
#include <vulkan/vulkan.h>

#include <cstdint>

#include "candela/render/gpu_context.h"

namespace candela::test {

class GpuTimer {
public:
    explicit GpuTimer(render::GpuContext& context) : context_(context) {
        VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
        info.queryType = VK_QUERY_TYPE_TIMESTAMP;
        info.queryCount = 2;
        vkCreateQueryPool(context_.device(), &info, nullptr, &pool_);
    }
    ~GpuTimer() { vkDestroyQueryPool(context_.device(), pool_, nullptr); }
    GpuTimer(const GpuTimer&) = delete;
    GpuTimer& operator=(const GpuTimer&) = delete;

    template <class F>
    double ms(F&& record) {
        context_.submitAndWait([&](VkCommandBuffer cmd) {
            vkCmdResetQueryPool(cmd, pool_, 0, 2);
            vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_NONE, pool_, 0);
            record(cmd);
            vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, pool_, 1);
        });
        uint64_t ticks[2] = {0, 0};
        vkGetQueryPoolResults(context_.device(), pool_, 0, 2, sizeof(ticks), ticks,
                              sizeof(uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT);
        return static_cast<double>(ticks[1] - ticks[0]) *
               static_cast<double>(context_.properties().limits.timestampPeriod) * 1e-6;
    }

private:
    render::GpuContext& context_;
    VkQueryPool pool_ = VK_NULL_HANDLE;
};

}  // namespace candela::test
