// Rows: light shafts (issue 16, Yusov 2014, GPU Pro 5, "High Performance Outdoor Light Scattering
// Using Epipolar Sampling"). Epipolar sampling with 1D min/max trees against the brute-force march
// (every pixel, 512 equal steps through the cascades) on the colonnade with the sun 14 degrees up
// behind its columns, at 640x360 and 1280x720 (quick: 160x96 with 128 slices of 128 samples).
// The frames hold the in-scattered radiance alone, so the error is the shafts' own. Error:
// mean |L - L_ref| / mean L_ref (green); the worst case gives the 99th percentile of
// |L - L_ref| / mean L_ref over the pixels and where the largest one is. Cost: rays marched
// (`scattering_samples`) and GPU time of the light-shaft passes (`scattering_ms`, median of the
// repetitions: 3 at 640x360, 1 at 1280x720), each mode against the reference. A further row gives
// the min/max tree's own gain: the same epipolar frame marched leaf by leaf.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "../colonnade_scene.h"
#include "median.h"
#include "report_context.h"

namespace candela::report {

using namespace candela::render;
using namespace candela::render::test;

namespace {

struct Rendered {
    CapturedFrame frame;
    double ms = 0.0;
    uint64_t rays = 0, steps = 0;
};

// `options` gives the sampling (scatteringSlices, scatteringSamples, scatteringSettings).
Rendered renderShafts(GpuContext& gpu, TestScene& scene, ScatteringMode mode,
                      RendererOptions options, uint32_t repetitions) {
    SceneResources resources(gpu);
    FrameInputs inputs = scene.prepare(resources);
    inputs.scene.atmosphere = content::Atmosphere{};
    options.scattering = mode;
    options.scatteringSettings.inscatteringOnly = true;
    Rendered r;
    std::vector<double> ms;
    FrameSequence frames(gpu, scene.width, scene.height, options);
    // GPU timestamps: the first frame's pipeline creation (CPU) and the atmosphere's tables
    // (not light-shaft passes) are not in scattering_ms.
    RendererStats stats;
    for (uint32_t i = 0; i < repetitions; ++i) {
        r.frame = frames.render(inputs, resources, &stats);
        ms.push_back(stats.scatteringMs);
    }
    r.ms = median(ms);
    r.rays = stats.scatteringSamples;
    r.steps = stats.scatteringSteps;
    return r;
}

struct Error {
    double mean = 0.0, p99 = 0.0, worst = 0.0;
    uint32_t worstX = 0, worstY = 0;
};

Error compare(const CapturedFrame& a, const CapturedFrame& reference) {
    const size_t pixels = reference.hdrRgb.size() / 3;
    double error = 0.0, total = 0.0;
    std::vector<double> differences(pixels);
    for (size_t p = 0; p < pixels; ++p) {
        const double d = std::abs(double(a.hdrRgb[3 * p + 1]) - reference.hdrRgb[3 * p + 1]);
        differences[p] = d;
        error += d;
        total += reference.hdrRgb[3 * p + 1];
    }
    Error e;
    const double mean = total / double(pixels);
    e.mean = error / total;
    const auto worst = std::max_element(differences.begin(), differences.end());
    e.worst = *worst / mean;
    e.worstX = uint32_t(size_t(worst - differences.begin()) % reference.width);
    e.worstY = uint32_t(size_t(worst - differences.begin()) / reference.width);
    std::nth_element(differences.begin(), differences.begin() + ptrdiff_t(pixels * 99 / 100),
                     differences.end());
    e.p99 = differences[pixels * 99 / 100] / mean;
    return e;
}

std::string ratio(double approximation, double reference) {
    return approximation > 0.0 ? formatNumber(reference / approximation) + "x" : "-";
}

}  // namespace

void addScatteringRows(ReportContext& context) {
    const bool quick = context.budget.quick;
    GpuContext& gpu = context.harness.context();
    // Quick (the smoke test): the unit test's size and slices, a fraction of a minute.
    RendererOptions settings;
    if (quick) settings.scatteringSlices = settings.scatteringSamples = 128;
    const std::vector<glm::uvec2> sizes = quick ? std::vector<glm::uvec2>{{160, 96}}
                                                : std::vector<glm::uvec2>{{640, 360}, {1280, 720}};
    for (const glm::uvec2& size : sizes) {
        // The brute-force frame takes minutes on lavapipe at 1280x720: one repetition there.
        const uint32_t repetitions = quick || size.x >= 1280 ? 1 : 3;
        TestScene scene = colonnadeScene(size.x, size.y);
        const Rendered reference =
            renderShafts(gpu, scene, ScatteringMode::BruteForce, settings, repetitions);
        const Rendered epipolar =
            renderShafts(gpu, scene, ScatteringMode::Epipolar, settings, repetitions);
        const Error e = compare(epipolar.frame, reference.frame);
        char name[96], metric[320], worst[192], cost[256];
        std::snprintf(name, sizeof(name), "Light shafts: epipolar, %ux%u", size.x, size.y);
        std::snprintf(metric, sizeof(metric),
                      "mean |L - L_ref| / mean L_ref of the in-scattered radiance (colonnade, "
                      "sun 14 deg up behind the columns; %u slices x %u samples, initial step "
                      "%u, threshold %s)",
                      settings.scatteringSlices, settings.scatteringSamples,
                      settings.scatteringSettings.initialStep,
                      formatNumber(settings.scatteringSettings.refinementThreshold).c_str());
        std::snprintf(worst, sizeof(worst),
                      "99th percentile %s of the mean; worst pixel %s of the mean at (%u, %u)",
                      formatNumber(e.p99).c_str(), formatNumber(e.worst).c_str(), e.worstX,
                      e.worstY);
        std::snprintf(cost, sizeof(cost), "rays %llu vs %llu (%s fewer); scattering %s",
                      (unsigned long long)epipolar.rays, (unsigned long long)reference.rays,
                      ratio(double(epipolar.rays), double(reference.rays)).c_str(),
                      formatCost(epipolar.ms, reference.ms, "ms").c_str());
        context.report.rows.push_back(
            {name,
             "brute force: every pixel, " +
                 std::to_string(settings.scatteringSettings.bruteForceSteps) +
                 " steps through every cascade",
             metric, e.mean, "rel", worst, cost});
        // The tree's own gain: the same samples, the march leaf by leaf.
        RendererOptions flat = settings;
        flat.scatteringSettings.minMaxTree = false;
        const Rendered leaves =
            renderShafts(gpu, scene, ScatteringMode::Epipolar, flat, repetitions);
        const Error same = compare(epipolar.frame, leaves.frame);
        std::snprintf(name, sizeof(name), "Light shafts: min/max tree, %ux%u", size.x, size.y);
        std::snprintf(cost, sizeof(cost), "shadow tests %llu vs %llu (%s fewer); scattering %s",
                      (unsigned long long)epipolar.steps, (unsigned long long)leaves.steps,
                      ratio(double(epipolar.steps), double(leaves.steps)).c_str(),
                      formatCost(epipolar.ms, leaves.ms, "ms").c_str());
        context.report.rows.push_back(
            {name, "the epipolar march leaf by leaf (no tree)",
             "mean |L - L_ref| / mean L_ref of the in-scattered radiance (the same frame)",
             same.mean, "rel", "worst pixel " + formatNumber(same.worst) + " of the mean", cost});
    }
}

}  // namespace candela::report
