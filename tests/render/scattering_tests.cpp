// Light shafts (issue 16, render/README.md "Light shafts"): epipolar sampling with 1D min/max
// trees against the brute-force march, on the colonnade with the sun behind its columns, at a
// small size (the 640x360 and 1280x720 figures are docs/speed-vs-error.md rows). The frames
// hold the in-scattered radiance alone (ScatteringSettings::inscatteringOnly), so the error is
// the shafts' own, not diluted by the surfaces behind them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "candela/render/gpu_context.h"
#include "colonnade_scene.h"

namespace candela::render::test {
namespace {

struct Shafts {
    CapturedFrame frame;
    RendererStats stats;
};

Shafts renderShafts(GpuContext& context, TestScene& scene, ScatteringMode mode,
                    const ScatteringSettings& settings) {
    SceneResources resources(context);
    FrameInputs inputs = scene.prepare(resources);
    inputs.scene.atmosphere = content::Atmosphere{};
    RendererOptions options;
    options.scattering = mode;
    options.scatteringSettings = settings;
    options.scatteringSettings.inscatteringOnly = true;
    options.shadowCascadeSize = 512;
    Shafts s;
    s.frame = renderOffscreen(context, inputs, scene.width, scene.height, 1, &resources, options,
                              &s.stats);
    EXPECT_EQ(s.frame.nonFiniteHdrValues(), 0u);
    return s;
}

// mean |a - b| / mean b over the green channel.
double meanRelativeError(const CapturedFrame& a, const CapturedFrame& b) {
    double error = 0.0, total = 0.0;
    for (size_t i = 1; i < b.hdrRgb.size(); i += 3) {
        error += std::abs(double(a.hdrRgb[i]) - b.hdrRgb[i]);
        total += b.hdrRgb[i];
    }
    return error / total;
}

// The shafts are there (the air the sun lights through the gaps is several times brighter than
// the air in the columns' shadows), and epipolar sampling stays within the 2% of the
// brute-force march with several times fewer rays. 128 slices of 128 samples: the defaults
// (512 x 256) are sized for 1280x720 and would hold more samples than this image has pixels.
TEST(LightShafts, EpipolarMatchesBruteForceThroughAColonnade) {
    GpuContext context(requiredValidation());
    TestScene scene = colonnadeScene(160, 96);
    ScatteringSettings settings;
    settings.slices = 128;
    settings.samplesPerSlice = 128;
    const Shafts reference = renderShafts(context, scene, ScatteringMode::BruteForce, settings);
    const Shafts epipolar = renderShafts(context, scene, ScatteringMode::Epipolar, settings);
    std::vector<float> green;
    for (size_t i = 1; i < reference.frame.hdrRgb.size(); i += 3)
        green.push_back(reference.frame.hdrRgb[i]);
    std::sort(green.begin(), green.end());
    const double contrast =
        green[green.size() * 9 / 10] / std::max(green[green.size() / 10], 1e-6f);
    const double error = meanRelativeError(epipolar.frame, reference.frame);
    std::printf(
        "90th / 10th percentile of the shafts %.2f; epipolar error %.4f; rays %llu vs "
        "%llu; shadow tests %llu vs %llu\n",
        contrast, error, (unsigned long long)epipolar.stats.scatteringSamples,
        (unsigned long long)reference.stats.scatteringSamples,
        (unsigned long long)epipolar.stats.scatteringSteps,
        (unsigned long long)reference.stats.scatteringSteps);
    EXPECT_GT(contrast, 2.0) << "the columns must cast shafts";
    EXPECT_LT(error, 0.02);
    EXPECT_EQ(reference.stats.scatteringSamples, uint64_t(scene.width) * scene.height);
    EXPECT_LT(epipolar.stats.scatteringSamples * 3, reference.stats.scatteringSamples);
    EXPECT_GT(epipolar.stats.scatteringMs, 0.0);
    EXPECT_EQ(context.validationMessages(), 0u);
}

}  // namespace
}  // namespace candela::render::test
