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
#include "offscreen_frame.h"

namespace candela::render::test {
namespace {

struct Shafts {
    CapturedFrame frame;
    RendererStats stats;
};

// `options` gives the sampling (scatteringSlices, scatteringSamples, scatteringSettings).
Shafts renderShafts(GpuContext& context, TestScene& scene, ScatteringMode mode,
                    RendererOptions options) {
    SceneResources resources(context);
    FrameInputs inputs = scene.prepare(resources);
    inputs.scene.atmosphere = content::Atmosphere{};
    options.scattering = mode;
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
    RendererOptions settings;
    settings.scatteringSlices = 128;
    settings.scatteringSamples = 128;
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

// Aerial perspective (render/README.md "Aerial perspective"): blended surfaces are drawn after
// the light shafts, so the air in front of them comes from a coarse grid of view rays. Two
// emissive panes in open air under a casting sun, one 80 m away, one 300 m away (past the
// grid's 200 m): blended at full coverage they must show what opaque panes there show after
// the shafts' reference march, at 400 times clear air's density (colonnade_shafts' haze), where
// the air takes over half of the near pane's light away and adds about as much.
TestScene airPanes(bool blended) {
    TestScene scene;
    scene.width = 48;
    scene.height = 48;
    content::Material pane = lambertWhite();
    pane.baseColorFactor = {0.0f, 0.0f, 0.0f, 1.0f};
    pane.emissiveFactor = {1.0f, 1.0f, 1.0f};
    pane.emissiveStrength = 50.0f;
    if (blended) pane.alphaMode = content::AlphaMode::Blend;
    const glm::mat4 facingCamera =
        glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(1.0f, 0.0f, 0.0f));
    scene.add(content::makePlane(20.0f, 1), pane,
              glm::translate(glm::mat4(1.0f), glm::vec3(-25.0f, 0.0f, -80.0f)) * facingCamera);
    scene.add(content::makePlane(70.0f, 1), pane,
              glm::translate(glm::mat4(1.0f), glm::vec3(90.0f, 0.0f, -300.0f)) * facingCamera);
    LightInstance sun;
    sun.light.type = content::LightType::Directional;
    sun.light.lux = 3000.0f;  // the air's light and the panes' about alike
    sun.light.castShadows = true;
    sun.direction = -glm::normalize(glm::vec3(0.5f, 0.8f, 0.6f));  // behind, above, right
    scene.lights.push_back(sun);
    scene.lookAt(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    return scene;
}

struct PaneFrame {
    CapturedFrame frame;
    bool aerialPerspective = false;  // the frame ran the aerial_perspective pass
};

PaneFrame renderPanes(GpuContext& context, bool blended, bool atmosphere) {
    TestScene scene = airPanes(blended);
    SceneResources resources(context);
    FrameInputs inputs = scene.prepare(resources);
    if (atmosphere) inputs.scene.atmosphere = content::Atmosphere{};
    RendererOptions options;
    // The opaque panes' air by the brute-force march (the reference the grid samples).
    options.scattering = ScatteringMode::BruteForce;
    options.scatteringSettings.densityScale = 400.0f;
    options.shadowCascadeSize = 256;
    RendererStats stats;
    PaneFrame f;
    f.frame =
        renderOffscreen(context, inputs, scene.width, scene.height, 1, &resources, options, &stats);
    EXPECT_EQ(f.frame.nonFiniteHdrValues(), 0u);
    f.aerialPerspective =
        std::any_of(stats.passMs.begin(), stats.passMs.end(),
                    [](const auto& pass) { return pass.first == "aerial_perspective"; });
    return f;
}

TEST(AerialPerspective, ABlendedPaneInTheAirLooksLikeAnOpaqueOne) {
    GpuContext& context = sharedContext();
    const PaneFrame opaque = renderPanes(context, false, true);
    const PaneFrame blended = renderPanes(context, true, true);
    const PaneFrame clearOpaque = renderPanes(context, false, false);
    const PaneFrame clearBlended = renderPanes(context, true, false);
    EXPECT_FALSE(opaque.aerialPerspective) << "nothing blended: no grid";
    EXPECT_TRUE(blended.aerialPerspective);
    EXPECT_FALSE(clearBlended.aerialPerspective) << "no atmosphere: no grid";
    // Inner pixels of each pane (the near one left of the centre, the far one right of it).
    struct Block {
        const char* name;
        uint32_t x0, x1, y0, y1;
    };
    for (const Block& b : {Block{"80 m", 6, 16, 18, 30}, Block{"300 m", 32, 44, 18, 30}}) {
        double worst = 0.0, mean = 0.0, change = 1.0, clearWorst = 0.0;
        uint32_t n = 0;
        for (uint32_t y = b.y0; y < b.y1; ++y) {
            for (uint32_t x = b.x0; x < b.x1; ++x) {
                const float* o = hdrPixel(opaque.frame, x, y);
                const float* t = hdrPixel(blended.frame, x, y);
                const float* co = hdrPixel(clearOpaque.frame, x, y);
                const float* ct = hdrPixel(clearBlended.frame, x, y);
                for (int c = 0; c < 3; ++c) {
                    const double e = std::abs(double(t[c]) - o[c]) / o[c];
                    worst = std::max(worst, e);
                    mean += e;
                    ++n;
                    change = std::min(change, std::abs(double(o[c]) - co[c]) / co[c]);
                    clearWorst = std::max(clearWorst, std::abs(double(ct[c]) - co[c]) / co[c]);
                }
            }
        }
        std::printf(
            "%s: blended against opaque, mean %.5f worst %.5f (the air changes the pane "
            "by at least %.3f); no atmosphere: worst %.6f\n",
            b.name, mean / n, worst, change, clearWorst);
        EXPECT_GT(change, 0.2) << b.name << ": the air must change the pane";
        EXPECT_LT(worst, 5e-3) << b.name;
        EXPECT_LT(clearWorst, 2e-3) << b.name;
    }
    EXPECT_EQ(context.validationMessages(), 0u);
}

}  // namespace
}  // namespace candela::render::test
