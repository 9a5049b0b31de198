// Rows (issue 21): the material extensions' image-based light against the reference mode, on
// the sphere rows of the IBL section (metal and grey dielectric, roughness 0..1) under a real
// sky: anisotropic spheres (strength 0.8; split sum with the bent reflection vector at the
// lobe's mean roughness), and clear-coated spheres (coat factor 1, coat roughness 0..1 with the
// column; the coat's split sum and the base under it scaled by 1 - c E_c). Errors over the
// spheres' pixels; cost from the lighting pass's GPU timestamps, against the same spheres
// without the extension (the variant that compiles it out).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <string>

#include "../ibl_sphere_rows.h"
#include "candela/render/environment.h"
#include "image_difference.h"
#include "median.h"
#include "report_context.h"

namespace candela::report {

using namespace candela::render;
using namespace candela::render::test;

namespace {

struct ModeRun {
    CapturedFrame image;
    std::vector<double> ms;
};

}  // namespace

void addMaterialRows(ReportContext& context) {
    const bool quick = context.budget.quick;
    GpuContext& gpu = context.harness.context();
    std::shared_ptr<const Environment> sky = loadReportSky(gpu);
    const uint32_t width = quick ? 96 : 288, height = quick ? 48 : 128;
    const uint32_t referenceSamples = quick ? 64 : 1024;
    const uint32_t repetitions = quick ? 1 : 3;
    SphereRows plain = sphereRows(sky, width, height);
    std::vector<bool> onSphere(size_t(width) * height);
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x)
            onSphere[size_t(y) * width + x] = sphereAtPixel(plain, x, y) >= 0;
    }
    auto spheres = [&](uint32_t x, uint32_t y) { return bool(onSphere[size_t(y) * width + x]); };

    struct Extension {
        const char* name;
        const char* reference;
        std::function<void(content::Material&, int column)> apply;
    };
    const Extension extensions[] = {
        {"Anisotropic IBL (bent reflection vector; split sum at the lobe's mean roughness)",
         "reference IBL with the anisotropic GGX (eq. 6 per pixel, MIS)",
         [](content::Material& m, int) { m.anisotropyStrength = 0.8f; }},
        {"Clear-coat split sum (second prefiltered read x LUT; base x (1 - c E_c))",
         "reference IBL with the coat lobe (eq. 6 per pixel, MIS)",
         [](content::Material& m, int column) {
             m.clearcoatFactor = 1.0f;
             m.clearcoatRoughnessFactor = float(column) / 5.0f;
         }},
    };
    for (const Extension& extension : extensions) {
        SphereRows rows = sphereRows(sky, width, height);
        for (size_t i = 0; i < rows.scene.model.materials.size(); ++i)
            extension.apply(rows.scene.model.materials[i], int(i % 6));
        std::map<IblMode, ModeRun> runs;
        std::vector<double> withoutMs;
        for (uint32_t r = 0; r < repetitions; ++r) {
            for (IblMode mode : {IblMode::SplitSum, IblMode::Reference}) {
                RendererOptions options;
                options.ibl = mode;
                options.referenceSamples = referenceSamples;
                RendererStats stats;
                runs[mode].image = rows.scene.render(gpu, options, &stats, 2);
                runs[mode].ms.push_back(stats.lightingMs);
            }
            RendererOptions options;
            RendererStats stats;
            plain.scene.render(gpu, options, &stats, 2);
            withoutMs.push_back(stats.lightingMs);
        }
        const CapturedFrame& reference = runs[IblMode::Reference].image;
        ImageDifference d = imageDifference(runs[IblMode::SplitSum].image, reference, spheres);
        char metric[240];
        std::snprintf(metric, sizeof(metric),
                      "relative RMSE over the spheres' pixels (12 spheres: metal and grey "
                      "dielectric, roughness 0..1; %ux%u, %s, no lights); reference: %u + %u "
                      "samples per pixel",
                      width, height, kReportSky, referenceSamples, referenceSamples);
        char where[240];
        std::snprintf(where, sizeof(where),
                      "max %.1f x the mean at pixel (%u, %u); energy bias %+.1f %%; lighting "
                      "pass without the extension %.2f ms",
                      d.relativeMax, d.worstX, d.worstY, 100.0 * d.relativeBias, median(withoutMs));
        context.report.rows.push_back(
            {extension.name, extension.reference, metric, d.relativeRmse, "rel RMSE", where,
             "lighting pass " + formatCost(median(runs[IblMode::SplitSum].ms),
                                           median(runs[IblMode::Reference].ms), "ms")});
    }
}

}  // namespace candela::report
