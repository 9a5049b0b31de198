// The renderer's post-processing on the HDR target after the scene's passes: TAA's resolve
// and copy-back, the motion-vector capture, auto exposure (meter, adapt, histogram) and
// bloom. Tonemapping and FXAA stay in Renderer::recordFrame, which orders these.

#include <array>
#include <cstdint>
#include <glm/gtc/packing.hpp>
#include <optional>
#include <span>
#include <string>

#include "candela/render/auto_exposure.h"
#include "candela/render/renderer.h"
#include "frame_graph/frame_graph.h"
#include "frame_graph/frame_graph_executor.h"
#include "frame_graph/image_copy_pass.h"
#include "passes/bloom/bloom_pass.h"
#include "passes/exposure/exposure_bindings.h"
#include "passes/exposure/exposure_pass.h"
#include "passes/taa/taa_pass.h"
#include "temporal_history.h"

namespace candela::render {

uint32_t Renderer::declareTaa(uint32_t hdrId, uint32_t hdrVersion, float exposure) {
    FrameGraph& g = *graph_;
    features_.push_back("taa");
    const TemporalHistory::Frame frame = taaHistory_->declare(g, "taa.history", "taa.resolved");
    const ResourceHandle history = frame.previous;
    ResourceHandle resolved = frame.written;
    ResourceHandle hdr{hdrId, hdrVersion};
    const ResourceHandle motion{motionId_, motionVersion_};
    const TaaPass::Settings settings{exposure, options_.taaMinimumBlend, frame.valid,
                                     options_.taaSharpness};
    {
        auto p = g.addPass("taa", PassKind::Device,
                           [this, hdr, motion, history, resolved, settings](PassContext& ctx) {
                               taaPass_->recordResolve(ctx.cmd(), ctx.image(hdr), ctx.image(motion),
                                                       ctx.image(history), ctx.image(resolved),
                                                       settings);
                           });
        p.read(hdr, Use::StorageRead);
        p.read(motion, Use::Sampled);
        p.read(history, Use::Sampled);
        resolved = p.write(resolved, Use::StorageWrite);
    }
    hdr = declareImageCopy(g, "taa_copy", resolved, hdr);
    return hdr.version;
}

void Renderer::declareMotionCapture() {
    FrameGraph& g = *graph_;
    const VkDeviceSize bytes = VkDeviceSize(width_) * height_ * 2 * sizeof(uint16_t);
    if (motionReadback_.size() != bytes) {
        motionReadback_ = GpuBuffer(context_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                    MemoryLocation::HostVisible);
    }
    const ResourceHandle motion{motionId_, motionVersion_};
    const ResourceHandle readback = g.importBuffer("motion.readback", &motionReadback_, true);
    auto p = g.addPass("motion_capture", PassKind::Device, [this, motion](PassContext& ctx) {
        VkBufferImageCopy region{};
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        region.imageExtent = {width_, height_, 1};
        vkCmdCopyImageToBuffer(ctx.cmd(), ctx.image(motion).handle(),
                               VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, motionReadback_.handle(), 1,
                               &region);
    });
    p.read(motion, Use::TransferSrc);
    p.write(readback, Use::TransferDst);
    p.sideEffect();
}

std::vector<glm::vec2> Renderer::motionVectors() const {
    std::vector<glm::vec2> motion;
    if (motionReadback_.size() == 0 || !frameRecorded_) return motion;
    const auto* halves = static_cast<const uint16_t*>(motionReadback_.mapped());
    motion.resize(size_t(width_) * height_);
    for (size_t i = 0; i < motion.size(); ++i)
        motion[i] = {glm::unpackHalf1x16(halves[i * 2]), glm::unpackHalf1x16(halves[i * 2 + 1])};
    return motion;
}

float Renderer::autoExposureEv100(const FrameInputs& inputs) {
    const AutoExposureSettings& settings = options_.autoExposure;
    if (histogramWritten_) {
        const auto* bins = static_cast<const uint32_t*>(histogram_.mapped());
        const std::optional<float> metered = meterEv100(std::span(bins, HISTOGRAM_BINS), settings);
        if (metered) {
            stats_.exposureEv100 = *metered;
            // The first metered frame starts adapted; later ones move towards the meter.
            adaptedEv100_ =
                adaptedEv100_ ? adaptEv100(*adaptedEv100_, *metered, inputs.deltaSeconds, settings)
                              : adaptEv100(0.0f, *metered, 1.0e9f, settings);
        }
    }
    if (!adaptedEv100_) return inputs.scene.camera.ev100;  // nothing metered yet
    stats_.adaptedEv100 = *adaptedEv100_;
    return *adaptedEv100_;
}

void Renderer::declareHistogram(uint32_t hdrId, uint32_t hdrVersion) {
    FrameGraph& g = *graph_;
    features_.push_back("auto_exposure");
    const ResourceHandle hdr{hdrId, hdrVersion};
    ResourceHandle histogram = g.importBuffer("exposure.histogram", &histogram_, true);
    {
        auto p = g.addPass("exposure_clear", PassKind::Device, [this](PassContext& ctx) {
            vkCmdFillBuffer(ctx.cmd(), histogram_.handle(), 0, VK_WHOLE_SIZE, 0u);
        });
        histogram = p.write(histogram, Use::TransferDst);
    }
    auto p = g.addPass("exposure_histogram", PassKind::Device, [this, hdr](PassContext& ctx) {
        histogramPass_->record(ctx.cmd(), ctx.image(hdr), histogram_);
    });
    p.read(hdr, Use::StorageRead);
    p.write(histogram, Use::StorageReadWrite);
    histogramWritten_ = true;
}

uint32_t Renderer::declareBloom(uint32_t hdrId, uint32_t hdrVersion) {
    FrameGraph& g = *graph_;
    features_.push_back("bloom");
    const uint32_t levelCount = BloomPass::levelCount(width_, height_);
    std::array<ResourceHandle, BLOOM_MAX_LEVELS> levels{};
    ResourceHandle source{hdrId, hdrVersion};
    for (uint32_t i = 0; i < levelCount; ++i) {
        ResourceHandle level = g.createImage("bloom.level" + std::to_string(i),
                                             BloomPass::levelDesc(i, width_, height_));
        auto p = g.addPass("bloom_down" + std::to_string(i), PassKind::Device,
                           [this, source, level](PassContext& ctx) {
                               bloomPass_->recordDownsample(ctx.cmd(), ctx.image(source),
                                                            ctx.image(level));
                           });
        p.read(source, Use::StorageRead);
        levels[i] = p.write(level, Use::StorageWrite);
        source = levels[i];
    }
    ResourceHandle hdr{hdrId, hdrVersion};
    const float strength = options_.bloomStrength;
    auto p = g.addPass("bloom_composite", PassKind::Device,
                       [this, hdr, levels, levelCount, strength](PassContext& ctx) {
                           std::array<ImageRef, BLOOM_MAX_LEVELS> images{};
                           for (uint32_t i = 0; i < levelCount; ++i)
                               images[i] = ctx.image(levels[i]);
                           bloomPass_->recordComposite(ctx.cmd(), ctx.image(hdr), images,
                                                       levelCount, strength);
                       });
    for (uint32_t i = 0; i < levelCount; ++i)
        p.read(levels[i], Use::Sampled);
    hdr = p.write(hdr, Use::StorageReadWrite);
    return hdr.version;
}

}  // namespace candela::render
