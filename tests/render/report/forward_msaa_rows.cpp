// Rows (in the antialiasing section): forward MSAA (issue 24) on the silhouette of blended
// geometry (the blended box of render_antialiasing_tests, the frame's only edge) against the
// 4x4 supersampled reference: edge RMSE of the displayed image for 1 sample and for each sample
// count the device supports, with the forward passes' cost.
#include <cstdio>
#include <stdexcept>
#include <string>

#include "../antialiasing_scenes.h"
#include "median.h"
#include "report_context.h"

namespace candela::report {

using namespace candela::render;
using namespace candela::render::test;

namespace {

double forwardPassMs(const RendererStats& stats, bool wholeFrame) {
    double ms = 0.0;
    for (const auto& [name, t] : stats.passMs) {
        if (wholeFrame || name.starts_with("forward_")) ms += t;
    }
    return ms;
}

}  // namespace

void addForwardMsaaRows(ReportContext& context) {
    const uint32_t width = 128, height = 96;
    const uint32_t repetitions = context.budget.quick ? 1 : 5;
    GpuContext& gpu = context.harness.context();
    const std::vector<float> reference =
        supersampledReference(gpu, &blendedBoxFromAbove, width, height);
    const std::vector<uint8_t> mask = edgeMask(reference, width, height);
    size_t edgePixels = 0;
    for (uint8_t v : mask)
        edgePixels += v;
    char metric[200];
    std::snprintf(metric, sizeof(metric),
                  "RMSE of displayed values (0-1) over the %zu edge pixels of a blended box's "
                  "silhouette, %ux%u",
                  edgePixels, width, height);

    double singleError = 0.0;
    for (uint32_t samples : {1u, 2u, 4u, 8u}) {
        std::vector<double> forwardMs, frameMs;
        std::vector<float> image;
        try {
            for (uint32_t r = 0; r < repetitions; ++r) {
                TestScene scene = blendedBoxFromAbove(width, height);
                RendererStats stats;
                // The 3rd frame is timed warm (the first includes shader compilation).
                image = displayed(renderStatic(gpu, scene, AntiAliasing::Off, 3, &stats, samples));
                forwardMs.push_back(forwardPassMs(stats, false));
                frameMs.push_back(forwardPassMs(stats, true));
            }
        } catch (const std::invalid_argument&) {
            continue;  // a sample count this device does not render
        }
        const double error = edgeRmse(image, reference, mask);
        if (samples == 1) singleError = error;
        char where[160];
        std::snprintf(where, sizeof(where),
                      samples == 1 ? "staircases on the blended silhouette"
                                   : "%.2f of 1 sample's error; opaque edges behind stay aliased",
                      error / singleError);
        const std::string name = samples == 1 ? std::string("Forward pass, 1 sample per pixel")
                                              : "Forward MSAA " + std::to_string(samples) +
                                                    "x (deferred result expanded, average resolve)";
        const std::string cost = "forward passes " + formatNumber(median(forwardMs)) +
                                 " ms, frame " + formatNumber(median(frameMs)) + " ms";
        context.report.rows.push_back({name, "4x4 supersampled, resolved in linear light", metric,
                                       error, "RMSE", where, cost});
    }
}

}  // namespace candela::report
