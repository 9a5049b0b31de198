// Rows: GTAO's sky visibility and its specular occlusion against the reference mode
// (rays marched against the same depth buffer), by radius and slice count, with the AO passes'
// GPU time: a black box on a floor under a uniform white sky (tests/render/
// ambient_occlusion_scene.h).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "../ambient_occlusion_scene.h"
#include "median.h"
#include "report_context.h"

namespace candela::report {

using namespace candela::render;
using namespace candela::render::test;

namespace {

struct Measured {
    CapturedFrame frame;
    double aoMs = 0.0;  // median over repetitions
};

Measured measure(BoxOnFloor& scene, AoMode mode, const BoxOnFloor::Settings& settings,
                 uint32_t repetitions, const RendererOptions* options = nullptr,
                 uint32_t frames = 2) {
    Measured m;
    std::vector<double> times;
    for (uint32_t r = 0; r < repetitions; ++r) {
        RendererStats stats;
        m.frame = scene.render(mode, settings, &stats, frames, options);
        times.push_back(stats.aoMs);
    }
    m.aoMs = median(times);
    return m;
}

// Mean |a / off - b / off| over open-floor pixels where b / off (the reference's share of the
// light) is under 0.9, and the worst pixel.
struct ShareError {
    double meanAbs = 0.0;
    double max = 0.0;
    uint32_t pixels = 0;
};

ShareError shareError(const BoxOnFloor& scene, const CapturedFrame& a, const CapturedFrame& b,
                      const CapturedFrame& off) {
    ShareError e;
    for (uint32_t y = 0; y < off.height; ++y) {
        for (uint32_t x = 0; x < off.width; ++x) {
            if (scene.trueVisibility(int(x), int(y)) < 0.0f) continue;
            const double unoccluded = hdrPixel(off, x, y)[1];
            if (unoccluded <= 1e-6) continue;
            const double reference = hdrPixel(b, x, y)[1] / unoccluded;
            if (reference >= 0.9) continue;
            const double error = std::abs(hdrPixel(a, x, y)[1] / unoccluded - reference);
            e.meanAbs += error;
            e.max = std::max(e.max, error);
            ++e.pixels;
        }
    }
    if (e.pixels) e.meanAbs /= e.pixels;
    return e;
}

// The diffuse rows' metric: the floor pixels compared, on a size x size frame.
void diffuseMetric(char* text, size_t bytes, uint32_t pixels, uint32_t size) {
    std::snprintf(text, bytes,
                  "mean |visibility - reference| over floor pixels the reference sees under 0.9 "
                  "(%u px; black box on a white floor, uniform sky, %ux%u)",
                  pixels, size, size);
}

}  // namespace

void addAmbientOcclusionRows(ReportContext& context) {
    const bool quick = context.budget.quick;
    const uint32_t size = quick ? 64 : 128;
    const uint32_t repetitions = quick ? 1 : 3;
    GpuContext& gpu = context.harness.context();
    BoxOnFloor diffuseScene(gpu, size);
    const Measured off = measure(diffuseScene, AoMode::Off, {}, 1);
    const std::vector<float> radii =
        quick ? std::vector<float>{1.0f} : std::vector<float>{0.5f, 1.0f, 2.0f};
    const std::vector<uint32_t> sliceCounts =
        quick ? std::vector<uint32_t>{4} : std::vector<uint32_t>{2, 4, 8};
    for (float radius : radii) {
        BoxOnFloor::Settings referenceSettings;
        referenceSettings.radius = radius;
        referenceSettings.referenceRays = quick ? 32 : 256;
        const Measured reference =
            measure(diffuseScene, AoMode::Reference, referenceSettings, repetitions);
        for (uint32_t slices : sliceCounts) {
            BoxOnFloor::Settings settings = referenceSettings;
            settings.slices = slices;
            const Measured gtao = measure(diffuseScene, AoMode::Gtao, settings, repetitions);
            const ShareError e = shareError(diffuseScene, gtao.frame, reference.frame, off.frame);
            char name[96], metric[240], where[96];
            std::snprintf(name, sizeof(name), "GTAO, radius %.1f m, %u slices x %u steps", radius,
                          slices, settings.steps);
            diffuseMetric(metric, sizeof(metric), e.pixels, size);
            std::snprintf(where, sizeof(where), "max %.3f", e.max);
            context.report.rows.push_back(
                {name,
                 "--ao reference (" + std::to_string(referenceSettings.referenceRays) +
                     " cosine rays x " + std::to_string(AmbientOcclusionSettings{}.referenceSteps) +
                     " steps, same radius)",
                 metric, e.meanAbs, "abs", where,
                 "AO passes " + formatCost(gtao.aoMs, reference.aoMs, "ms")});
        }
    }

    // Temporal accumulation: a still view, 16 frames of rotated slices (--aa off, so the
    // image is AO's own average), against the same reference at the default radius.
    {
        BoxOnFloor::Settings settings;
        settings.referenceRays = quick ? 32 : 256;
        const Measured reference = measure(diffuseScene, AoMode::Reference, settings, repetitions);
        const Measured single = measure(diffuseScene, AoMode::Gtao, settings, repetitions);
        RendererOptions options = BoxOnFloor::optionsFor(AoMode::Gtao, settings);
        options.aoSettings.temporal = AoTemporal::Always;
        const uint32_t frames = options.aoSettings.temporalFrames;
        const Measured accumulated =
            measure(diffuseScene, AoMode::Gtao, settings, repetitions, &options, frames);
        for (const auto& [label, m] :
             {std::pair{"1 frame", &single}, std::pair{"temporal, 16 frames", &accumulated}}) {
            const ShareError e = shareError(diffuseScene, m->frame, reference.frame, off.frame);
            char name[96], metric[240], where[96];
            std::snprintf(name, sizeof(name), "GTAO, radius %.1f m, %u slices, %s", settings.radius,
                          settings.slices, label);
            diffuseMetric(metric, sizeof(metric), e.pixels, size);
            std::snprintf(where, sizeof(where), "max %.3f", e.max);
            context.report.rows.push_back(
                {name, "--ao reference (same radius)", metric, e.meanAbs, "abs", where,
                 "AO passes per frame " + formatCost(m->aoMs, reference.aoMs, "ms")});
        }
    }

    // Specular occlusion: a black glossy floor (specular only), GTAO's two estimates (from
    // the visibility; from the horizons of the slice that holds the reflection vector) against
    // the reference's rays drawn from the GGX lobe.
    for (float roughness :
         quick ? std::vector<float>{0.5f} : std::vector<float>{0.2f, 0.5f, 0.8f}) {
        content::Material glossy = lambertWhite();
        glossy.baseColorFactor = {0.0f, 0.0f, 0.0f, 1.0f};
        glossy.specular = 1.0f;
        glossy.roughnessFactor = roughness;
        BoxOnFloor specularScene(gpu, size, glossy);
        BoxOnFloor::Settings settings;
        settings.referenceRays = quick ? 32 : 256;
        const Measured specularOff = measure(specularScene, AoMode::Off, settings, 1);
        const Measured reference = measure(specularScene, AoMode::Reference, settings, 1);
        for (AoSpecular source : {AoSpecular::FromVisibility, AoSpecular::HorizonSlice}) {
            RendererOptions options = BoxOnFloor::optionsFor(AoMode::Gtao, settings);
            options.aoSettings.specular = source;
            const Measured gtao = measure(specularScene, AoMode::Gtao, settings, 1, &options);
            const ShareError e =
                shareError(specularScene, gtao.frame, reference.frame, specularOff.frame);
            char name[112], metric[240], where[96];
            std::snprintf(name, sizeof(name), "GTAO specular occlusion (%s), roughness %.1f",
                          source == AoSpecular::FromVisibility ? "from visibility, default"
                                                               : "horizon slice through R",
                          roughness);
            std::snprintf(metric, sizeof(metric),
                          "mean |occluded / unoccluded specular - reference| where the reference "
                          "is under 0.9 (%u px; black glossy floor, radius 1.5 m, %ux%u)",
                          e.pixels, size, size);
            std::snprintf(where, sizeof(where), "max %.3f", e.max);
            context.report.rows.push_back(
                {name, "--ao reference (rays from the GGX lobe's visible normals)", metric,
                 e.meanAbs, "abs", where,
                 "AO passes " + formatCost(gtao.aoMs, reference.aoMs, "ms")});
        }
    }
}

}  // namespace candela::report
