// Rows: antialiasing (issue 24) against a 4x4 supersampled reference on the box-on-a-floor
// and colonnade scenes of render_antialiasing_tests: edge RMSE of the displayed image for no
// AA, FXAA, TAA after 16 static frames, with each one's cost; per scene a table with both
// resolve conventions and the reference's own cost.
#include <algorithm>
#include <cstdio>
#include <string>

#include "../antialiasing_scenes.h"
#include "median.h"
#include "report_context.h"

namespace candela::report {

using namespace candela::render;
using namespace candela::render::test;

namespace {

double passMs(const RendererStats& stats, const std::string& prefix) {
    double ms = 0.0;
    for (const auto& [name, t] : stats.passMs) {
        if (prefix.empty() || name.starts_with(prefix)) ms += t;
    }
    return ms;
}

struct Measured {
    std::vector<float> image;
    double aaMs = 0.0;     // the AA passes alone, median
    double frameMs = 0.0;  // every pass of the frame, median
};

using SceneMaker = TestScene (*)(uint32_t, uint32_t);

Measured measure(GpuContext& gpu, SceneMaker make, AntiAliasing aa, uint32_t frames,
                 uint32_t repetitions, uint32_t width, uint32_t height) {
    Measured m;
    std::vector<double> aaMs, frameMs;
    for (uint32_t r = 0; r < repetitions; ++r) {
        TestScene scene = make(width, height);
        RendererStats stats;
        CapturedFrame frame = renderStatic(gpu, scene, aa, frames, &stats);
        m.image = displayed(frame);
        aaMs.push_back(aa == AntiAliasing::Taa    ? passMs(stats, "taa")
                       : aa == AntiAliasing::Fxaa ? passMs(stats, "fxaa")
                                                  : 0.0);
        frameMs.push_back(passMs(stats, ""));
    }
    m.aaMs = median(aaMs);
    m.frameMs = median(frameMs);
    return m;
}

std::string ms(double value) {
    return formatNumber(value) + " ms";
}

// One scene's rows and table.
void addSceneRows(ReportContext& context, SceneMaker make, const char* sceneName,
                  const char* tableTitle) {
    const bool quick = context.budget.quick;
    const uint32_t width = 128, height = 96;
    const uint32_t repetitions = quick ? 1 : 5;
    GpuContext& gpu = context.harness.context();
    const std::vector<float> linear = supersampledReference(gpu, make, width, height);
    const std::vector<float> displayedAverage =
        supersampledReference(gpu, make, width, height, ResolveConvention::Displayed);
    const std::vector<uint8_t> mask = edgeMask(linear, width, height);
    size_t edgePixels = 0;
    for (uint8_t v : mask)
        edgePixels += v;

    // The reference's cost: one frame at 4x4 the pixels.
    std::vector<double> referenceMs;
    for (uint32_t r = 0; r < repetitions; ++r) {
        TestScene big = make(width * 4, height * 4);
        RendererStats stats;
        renderStatic(gpu, big, AntiAliasing::Off, 2, &stats);  // timed on the warm 2nd frame
        referenceMs.push_back(passMs(stats, ""));
    }
    const double reference = median(referenceMs);

    // Without jitter every frame of a static scene is the same image: the 3rd is timed warm
    // (a renderer's first frame includes the driver's shader compilation), like TAA's 16th.
    const Measured off = measure(gpu, make, AntiAliasing::Off, 3, repetitions, width, height);
    const Measured fxaa = measure(gpu, make, AntiAliasing::Fxaa, 3, repetitions, width, height);
    const Measured taa = measure(gpu, make, AntiAliasing::Taa, 16, repetitions, width, height);

    char metric[220];
    std::snprintf(metric, sizeof(metric),
                  "RMSE of displayed values (0-1) over the %zu edge pixels of %s, %ux%u",
                  edgePixels, sceneName, width, height);
    const char* referenceName = "4x4 supersampled, resolved in linear light";
    struct Mode {
        const char* name;
        const Measured* m;
        const char* where;
    };
    const double offError = edgeRmse(off.image, linear, mask);
    const Mode modes[] = {
        {"No antialiasing (1 sample per pixel)", &off, "staircases on every silhouette"},
        {"FXAA (post-process, linear-light blend)", &fxaa, "corners and sub-pixel detail"},
        {"TAA after 16 static frames (Halton 16)", &taa, "near-vertical edges"}};
    for (const Mode& mode : modes) {
        const double error = edgeRmse(mode.m->image, linear, mask);
        char where[160];
        std::snprintf(where, sizeof(where), "%.2f of no AA's error; %s", error / offError,
                      mode.where);
        const std::string cost = (mode.m == &off ? std::string("frame ")
                                                 : "AA passes " + ms(mode.m->aaMs) + ", frame ") +
                                 formatCost(mode.m->frameMs, reference, "ms") +
                                 " (reference frame at 16x pixels)";
        context.report.rows.push_back(
            {mode.name, referenceName, metric, error, "RMSE", where, cost});
    }

    ReportTable table;
    table.title = tableTitle;
    table.intro =
        std::string("Edge RMSE of the displayed image of ") + sceneName +
        " against the 4x4 supersampled reference, with the "
        "reference's 16 samples averaged in linear light (radiance, then tonemapped: the "
        "convention TAA resolves in, and the one the tests gate on) or averaged as displayed "
        "(each sample tonemapped first). Costs are GPU pass times on this device, medians of " +
        std::to_string(repetitions) + ".";
    table.header = {"mode", "linear-light reference", "displayed-average reference", "AA passes",
                    "whole frame"};
    for (const Mode& mode : modes) {
        table.rows.push_back({mode.name, formatNumber(edgeRmse(mode.m->image, linear, mask)),
                              formatNumber(edgeRmse(mode.m->image, displayedAverage, mask)),
                              mode.m == &off ? "-" : ms(mode.m->aaMs), ms(mode.m->frameMs)});
    }
    table.rows.push_back({"4x4 supersampled reference", "0", "-", "-", ms(reference)});
    context.report.tables.push_back(std::move(table));
}

}  // namespace

void addAntialiasingRows(ReportContext& context) {
    addSceneRows(context, &boxOnFloor, "a box on a floor under a sun",
                 "Antialiasing: edge error by resolve convention");
    addSceneRows(context, &colonnade,
                 "the demo's colonnade (pillars, plinths, capitals and a lintel) under a sun",
                 "Antialiasing: edge error on the colonnade");
}

}  // namespace candela::report
