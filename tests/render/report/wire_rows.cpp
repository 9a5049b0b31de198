// Rows: wires (issue 19, Persson 2014, GPU Pro 5, "Wire Antialiasing"). An unlit emissive wire
// across a 64x64 view, 20 px down to 0.1 px wide: the worst error of the radiance summed down a
// column against width x radiance (energy), and the worst change of a column sum while a 0.3 px
// wire moves by 1/8 pixel over 16 frames (flicker); Persson's clamp with coverage against the naive
// line a pixel wide, with the wire pass's cost for 2,000 segments at 256x256.
#include <cmath>
#include <cstdio>
#include <string>

#include "../wire_scene.h"
#include "median.h"
#include "report_context.h"

namespace candela::report {

using namespace candela::render;
using namespace candela::render::test;
using namespace candela::render::test::wires;

namespace {

struct WireMeasure {
    double energyError = 0.0;
    float worstWidth = 0.0f;
    double flicker = 0.0;
};

WireMeasure measure(GpuContext& gpu, WireMode mode) {
    RendererOptions options;
    options.wires = mode;
    SceneResources resources(gpu);
    FrameSequence frames(gpu, kSize, kSize, options);
    WireScene scene;
    WireMeasure out;
    for (float width : {20.0f, 7.0f, 2.5f, 1.0f, 0.6f, 0.3f, 0.1f}) {
        const float depth = depthForWidth(width);
        const float pixel = 2.0f * depth * std::tan(kFov / 2.0f) / float(kSize);
        const double error = worstColumnError(
            frames.render(scene.place(depth, 0.3f * pixel), resources), double(width) * kEmission);
        if (error > out.energyError) {
            out.energyError = error;
            out.worstWidth = width;
        }
    }
    const float depth = depthForWidth(0.3f);
    const float pixel = 2.0f * depth * std::tan(kFov / 2.0f) / float(kSize);
    std::vector<std::vector<double>> sums;
    for (int step = 0; step < 16; ++step)
        sums.push_back(
            columnSums(frames.render(scene.place(depth, float(step) * pixel / 8.0f), resources)));
    for (uint32_t x = 0; x < kSize; ++x) {
        double lo = sums[0][x], hi = sums[0][x];
        for (const auto& frame : sums) {
            lo = std::min(lo, frame[x]);
            hi = std::max(hi, frame[x]);
        }
        out.flicker = std::max(out.flicker, (hi - lo) / (0.3 * kEmission));
    }
    return out;
}

// The wire pass's median GPU time for 2,000 segments (40 wires of 50) at 256x256, lit by the
// default placeholder sky: the third frame on, so shader compilation is left out.
double passMs(GpuContext& gpu, WireMode mode, uint32_t repetitions) {
    RendererOptions options;
    options.wires = mode;
    SceneResources resources(gpu);
    FrameSequence frames(gpu, 256, 256, options);
    std::vector<candela::content::Wire> wires(40);
    candela::content::Material cable;
    cable.metallicFactor = 1.0f;
    cable.roughnessFactor = 0.4f;
    std::vector<WireDraw> draws;
    for (size_t w = 0; w < wires.size(); ++w) {
        wires[w].radius = 0.01f;
        for (uint32_t i = 0; i <= 50; ++i) {
            const float x = -20.0f + 40.0f * float(i) / 50.0f;
            wires[w].positions.push_back(
                {x, -2.0f + 0.1f * float(w) - 0.002f * x * x, -10.0f - float(w)});
            if (i > 0) wires[w].segments.insert(wires[w].segments.end(), {i - 1, i});
        }
        draws.push_back({&wires[w], &cable, glm::mat4(1.0f)});
    }
    FrameInputs inputs;
    inputs.scene.camera.projection = reverseZPerspective(glm::radians(60.0f), 1.0f, 0.05f);
    inputs.scene.wires = draws;
    std::vector<double> ms;
    for (uint32_t r = 0; r < repetitions + 2; ++r) {
        RendererStats stats;
        frames.render(inputs, resources, &stats);
        if (r < 2) continue;
        for (const auto& [name, t] : stats.passMs) {
            if (name == "wires") ms.push_back(t);
        }
    }
    return ms.empty() ? 0.0 : median(ms);
}

}  // namespace

void addWireRows(ReportContext& context) {
    GpuContext& gpu = context.harness.context();
    const uint32_t repetitions = context.budget.quick ? 1 : 7;
    const WireMeasure coverage = measure(gpu, WireMode::Coverage);
    const WireMeasure naive = measure(gpu, WireMode::Naive);
    const double coverageMs = passMs(gpu, WireMode::Coverage, repetitions);
    const double naiveMs = passMs(gpu, WireMode::Naive, repetitions);
    const std::string metric =
        "worst |column radiance sum / (width x radiance) - 1| over 64 columns, an unlit wire "
        "20, 7, 2.5, 1, 0.6, 0.3, 0.1 px wide, 64x64";
    char worst[200], cost[200];
    std::snprintf(worst, sizeof(worst),
                  "%.3g px wide; flicker (a 0.3 px wire moved by 1/8 px, 16 frames): column sums "
                  "change by %.2g%%",
                  coverage.worstWidth, 100.0 * coverage.flicker);
    std::snprintf(cost, sizeof(cost), "wire pass %s vs %s ms (2,000 segments, 256x256)",
                  formatNumber(coverageMs).c_str(), formatNumber(naiveMs).c_str());
    context.report.rows.push_back(
        {"Wires: Persson's clamp to a pixel's radius, alpha x real / "
         "clamped radius, coverage from the centre-line distance "
         "(Persson 2014, GPU Pro 5)",
         "width x radiance (the wire's energy)", metric, 100.0 * coverage.energyError, "% energy",
         worst, cost});
    std::snprintf(worst, sizeof(worst),
                  "%.3g px wide (a pixel-wide line, 1 / width too bright); flicker: column sums "
                  "change by %.2g%% (the line jumps a whole row instead)",
                  naive.worstWidth, 100.0 * naive.flicker);
    std::snprintf(cost, sizeof(cost), "wire pass %s ms (2,000 segments, 256x256)",
                  formatNumber(naiveMs).c_str());
    context.report.rows.push_back({"Wires: naive line one pixel wide at full alpha",
                                   "width x radiance (the wire's energy)", metric,
                                   100.0 * naive.energyError, "% energy", worst, cost});
}

}  // namespace candela::report
