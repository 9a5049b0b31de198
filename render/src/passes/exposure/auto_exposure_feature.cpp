#include "passes/exposure/auto_exposure_feature.h"

#include <span>

#include "candela/render/auto_exposure.h"
#include "candela/render/frame_inputs.h"
#include "features/scene_targets.h"
#include "frame_graph/frame_graph_executor.h"
#include "passes/exposure/exposure_bindings.h"
#include "passes/exposure/exposure_pass.h"

namespace candela::render {

AutoExposureFeature::AutoExposureFeature(GpuContext& context) : context_(context) {}

AutoExposureFeature::~AutoExposureFeature() = default;

bool AutoExposureFeature::active(const FeatureFrame& frame) const {
    return frame.options.exposure == ExposureMode::Auto;
}

float AutoExposureFeature::ev100(const FrameInputs& inputs, const AutoExposureSettings& settings,
                                 RendererStats& stats) {
    if (histogramWritten_) {
        const auto* bins = static_cast<const uint32_t*>(histogram_.mapped());
        const std::optional<float> metered = meterEv100(std::span(bins, HISTOGRAM_BINS), settings);
        if (metered) {
            stats.exposureEv100 = *metered;
            // The first metered frame starts adapted; later ones move towards the meter.
            adaptedEv100_ =
                adaptedEv100_ ? adaptEv100(*adaptedEv100_, *metered, inputs.deltaSeconds, settings)
                              : adaptEv100(0.0f, *metered, 1.0e9f, settings);
        }
    }
    if (!adaptedEv100_) return inputs.scene.camera.ev100;  // nothing metered yet
    stats.adaptedEv100 = *adaptedEv100_;
    return *adaptedEv100_;
}

void AutoExposureFeature::declare(FeatureFrame& frame) {
    frame.features.push_back("auto_exposure");
    if (!pass_) {
        pass_ = std::make_unique<ExposureHistogramPass>(context_);
        histogram_ =
            GpuBuffer(context_, HISTOGRAM_BINS * sizeof(uint32_t),
                      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                      MemoryLocation::HostVisible);
    }
    FrameGraph& g = frame.graph;
    const ResourceHandle hdr = frame.board.get<SceneTargets>().hdr;
    ResourceHandle histogram = g.importBuffer("exposure.histogram", &histogram_, true);
    const GpuBuffer* buffer = &histogram_;
    {
        auto p = g.addPass("exposure_clear", PassKind::Device, [buffer](PassContext& ctx) {
            vkCmdFillBuffer(ctx.cmd(), buffer->handle(), 0, VK_WHOLE_SIZE, 0u);
        });
        histogram = p.write(histogram, Use::TransferDst);
    }
    const ExposureHistogramPass* pass = pass_.get();
    auto p =
        g.addPass("exposure_histogram", PassKind::Device, [pass, buffer, hdr](PassContext& ctx) {
            pass->record(ctx.cmd(), ctx.image(hdr), *buffer);
        });
    p.read(hdr, Use::StorageRead);
    p.write(histogram, Use::StorageReadWrite);
    histogramWritten_ = true;
}

}  // namespace candela::render
