#include "temporal_history.h"

#include <vector>

#include "vk/image_transfer.h"

namespace candela::render {

void TemporalHistory::create(GpuContext& context, const ImageDesc& desc, uint32_t texelBytes) {
    const std::vector<uint8_t> zeros(size_t(desc.width) * desc.height * texelBytes, 0);
    for (GpuImage& image : images_) {
        image = GpuImage(context, desc);
        writeImage(context, image, texelBytes, zeros.data());
    }
    write_ = 0;
    valid_ = false;
}

void TemporalHistory::ensure(GpuContext& context, const ImageDesc& desc, uint32_t texelBytes) {
    const ImageDesc& now = images_[0].desc();
    if (created() && now.format == desc.format && now.width == desc.width &&
        now.height == desc.height) {
        return;
    }
    create(context, desc, texelBytes);
}

TemporalHistory::Frame TemporalHistory::declare(FrameGraph& graph, std::string previousName,
                                                std::string writtenName) {
    constexpr ImageState kSampledByCompute{VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                                           VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                           VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};
    constexpr ImageState kDiscard{VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                  0};
    Frame frame;
    frame.previous = graph.importImage(std::move(previousName), &images_[write_ ^ 1u],
                                       kSampledByCompute, ImageState{});
    frame.written =
        graph.importImage(std::move(writtenName), &images_[write_], kDiscard, kSampledByCompute);
    frame.valid = valid_;
    write_ ^= 1u;
    valid_ = true;
    return frame;
}

}  // namespace candela::render
