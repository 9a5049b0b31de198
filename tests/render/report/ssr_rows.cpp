// Rows: screen-space reflections by Hi-Z tracing against the linear reference march, on a
// floor under an emissive box (tests/render/ssr_scene.h), by floor roughness, with the SSR
// passes' GPU time and steps per ray; and a table of linear marches by step size against the
// CPU ray trace of the mirror case, for the steps a linear march needs to reach Hi-Z's hit
// accuracy.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "../ssr_scene.h"
#include "median.h"
#include "report_context.h"

namespace candela::report {

using namespace candela::render;
using namespace candela::render::test;

namespace {

struct Measured {
    CapturedFrame frame;
    RendererStats stats;  // the last repetition's
    double ssrMs = 0.0;   // median over repetitions
};

Measured measure(GpuContext& gpu, MirrorUnderBox& scene, const RendererOptions& options,
                 uint32_t repetitions) {
    Measured m;
    std::vector<double> times;
    for (uint32_t r = 0; r < repetitions; ++r) {
        m.frame = scene.scene().render(gpu, options, &m.stats);
        times.push_back(m.stats.ssrMs);
    }
    m.ssrMs = median(times);
    return m;
}

RendererOptions optionsFor(SsrMode mode, float referenceStep = SsrSettings{}.referenceStepPixels) {
    RendererOptions options;
    options.ssr = mode;
    options.ssrSettings.referenceStepPixels = referenceStep;
    return options;
}

std::string steps(const RendererStats& s) {
    char text[64];
    std::snprintf(text, sizeof(text), "%.1f mean / %u max", s.ssrStepsMean, s.ssrStepsMax);
    return text;
}

}  // namespace

void addSsrRows(ReportContext& context) {
    const bool quick = context.budget.quick;
    const uint32_t size = quick ? 64 : 128;
    const uint32_t repetitions = quick ? 1 : 3;
    GpuContext& gpu = context.harness.context();

    // Hi-Z against the reference by roughness: the floor's radiance, relative to the box's.
    // The reference traces the lobe (64 GGX rays per rough pixel, full resolution, no
    // pre-convolution); Hi-Z traces one ray and cone-traces the pre-convolved scene around it,
    // or (the row below each) reads the pre-convolved scene once at the hit.
    for (float roughness :
         quick ? std::vector<float>{0.0f} : std::vector<float>{0.0f, 0.1f, 0.2f, 0.4f}) {
        MirrorUnderBox scene(size, size, roughness);
        const Measured reference = measure(gpu, scene, optionsFor(SsrMode::Reference), repetitions);
        const MirrorComparison boxSeen = compareMirror(scene, reference.frame);
        const double box = std::max(boxSeen.boxRadiance, 1e-6);
        const bool atCutoff = roughness >= SsrSettings{}.roughnessCutoff;
        for (bool cone : {true, false}) {
            if (!cone && (roughness == 0.0f || atCutoff)) continue;  // the same image
            RendererOptions hizOptions = optionsFor(SsrMode::Hiz);
            hizOptions.ssrSettings.coneTracing = cone;
            const Measured hiz = measure(gpu, scene, hizOptions, repetitions);
            double sum = 0.0, worst = 0.0;
            uint32_t pixels = 0;
            for (uint32_t y = 0; y < size; ++y) {
                for (uint32_t x = 0; x < size; ++x) {
                    if (scene.truth(int(x), int(y)) == MirrorUnderBox::Truth::NotFloor) continue;
                    const double e = std::abs(hdrPixel(hiz.frame, x, y)[1] -
                                              hdrPixel(reference.frame, x, y)[1]) /
                                     box;
                    sum += e;
                    worst = std::max(worst, e);
                    ++pixels;
                }
            }
            char name[160], metric[256], where[160];
            std::snprintf(name, sizeof(name), "SSR Hi-Z (--ssr hiz)%s, roughness %.1f%s",
                          cone ? "" : ", one pre-convolved read at the hit (no cone tracing)",
                          roughness, atCutoff ? " (at the cut-off: sky only)" : "");
            std::snprintf(metric, sizeof(metric),
                          "mean |floor radiance - reference| / box radiance over floor pixels "
                          "(%u px; metal floor under an emissive box, no sky, %ux%u)",
                          pixels, size, size);
            std::snprintf(where, sizeof(where),
                          "max %.3f; steps per pixel %s vs %s; hit rate %.3f vs %.3f", worst,
                          steps(hiz.stats).c_str(), steps(reference.stats).c_str(),
                          hiz.stats.ssrHitRate, reference.stats.ssrHitRate);
            context.report.rows.push_back(
                {name,
                 roughness > 0.0f && !atCutoff
                     ? "--ssr reference (64 GGX lobe rays per pixel, linear march, 0.5 px steps)"
                     : "--ssr reference (linear march, 0.5 px steps)",
                 metric, pixels ? sum / pixels : 0.0, "rel", where,
                 "SSR passes " + formatCost(hiz.ssrMs, reference.ssrMs, "ms")});
        }
    }

    // The mirror case against the CPU ray trace: Hi-Z, and linear marches by step size.
    MirrorUnderBox mirror(size, size);
    ReportTable table;
    table.title = "SSR: steps for the same hit accuracy (mirror case)";
    table.intro =
        "Floor pixels (edges ±1 px left out) whose radiance is off the CPU ray trace's (the box's "
        "radiance where the mirror ray meets it, black elsewhere) by over 2% of the box's, for "
        "Hi-Z and for linear marches by step size; steps per traced ray from --stats.";
    table.header = {"trace", "wrong pixels", "of", "steps mean", "steps max", "SSR ms"};
    auto addRow = [&](const std::string& label, const RendererOptions& options) {
        const Measured m = measure(gpu, mirror, options, repetitions);
        const MirrorComparison c = compareMirror(mirror, m.frame);
        table.rows.push_back({label, std::to_string(c.boxPixelsWrong + c.blackPixelsWrong),
                              std::to_string(c.boxPixels + c.blackPixels),
                              formatNumber(m.stats.ssrStepsMean),
                              std::to_string(m.stats.ssrStepsMax), formatNumber(m.ssrMs)});
    };
    addRow("Hi-Z (--ssr hiz)", optionsFor(SsrMode::Hiz));
    for (float step :
         quick ? std::vector<float>{0.5f} : std::vector<float>{0.5f, 1.0f, 2.0f, 4.0f}) {
        char label[64];
        std::snprintf(label, sizeof(label), "linear, %.1f px steps", step);
        addRow(label, optionsFor(SsrMode::Reference, step));
    }
    context.report.tables.push_back(std::move(table));
}

}  // namespace candela::report
