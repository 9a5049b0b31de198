// Rows: split-sum and mobile image-based lighting against the reference mode (eq. 6 by Monte
// Carlo per pixel), as images: two rows of spheres (metal, dielectric; roughness 0..1) under a
// real sky, RMSE over the spheres' pixels; cost from the lighting pass's GPU timestamps.
#include <algorithm>
#include <cstdio>
#include <filesystem>
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


std::shared_ptr<const Environment> loadReportSky(GpuContext& gpu) {
    content::Diagnostics diagnostics;
    EnvironmentCacheOptions cache{std::filesystem::temp_directory_path() / "candela_report_sky"};
    std::shared_ptr<const Environment> sky = Environment::load(
        gpu, std::filesystem::path(CANDELA_SHARED_ASSETS) / kReportSky, diagnostics, cache);
    if (sky->stats().fallback) {
        throw std::runtime_error(std::string("cannot load the report's sky ") + kReportSky + ": " +
                                 diagnostics.toString());
    }
    return sky;
}

void addSplitSumRow(ReportContext& context) {
    const bool quick = context.budget.quick;
    GpuContext& gpu = context.harness.context();
    std::shared_ptr<const Environment> sky = loadReportSky(gpu);
    const uint32_t width = quick ? 96 : 288, height = quick ? 48 : 128;
    const uint32_t referenceSamples = quick ? 64 : 2048;
    const uint32_t repetitions = quick ? 1 : 3;
    SphereRows rows = sphereRows(sky, width, height);
    std::map<IblMode, CapturedFrame> images;
    std::map<IblMode, std::vector<double>> ms;
    for (uint32_t r = 0; r < repetitions; ++r) {
        for (IblMode mode : {IblMode::SplitSum, IblMode::Mobile, IblMode::Reference}) {
            RendererOptions options;
            options.ibl = mode;
            options.referenceSamples = referenceSamples;
            RendererStats stats;
            images[mode] = rows.scene.render(gpu, options, &stats, 2);
            ms[mode].push_back(stats.lightingMs);
        }
    }
    std::vector<int> sphereOfPixel(size_t(width) * height);
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x)
            sphereOfPixel[size_t(y) * width + x] = sphereAtPixel(rows, x, y);
    }
    auto spheres = [&](int first, int last) {
        return [&, first, last](uint32_t x, uint32_t y) {
            int i = sphereOfPixel[size_t(y) * width + x];
            return i >= first && i <= last;
        };
    };
    char metric[240];
    std::snprintf(metric, sizeof(metric),
                  "relative RMSE over the spheres' pixels (12 spheres: metal and grey dielectric, "
                  "roughness 0..1; %ux%u, %s, no lights); reference: %u + %u samples per pixel",
                  width, height, kReportSky, referenceSamples, referenceSamples);
    for (IblMode mode : {IblMode::SplitSum, IblMode::Mobile}) {
        const CapturedFrame& reference = images[IblMode::Reference];
        ImageDifference d = imageDifference(images[mode], reference, spheres(0, 11));
        ImageDifference metals = imageDifference(images[mode], reference, spheres(0, 5));
        ImageDifference dielectrics = imageDifference(images[mode], reference, spheres(6, 11));
        char where[240];
        std::snprintf(where, sizeof(where),
                      "max %.1f x the mean at pixel (%u, %u); RMSE metals %.2f, dielectrics "
                      "%.3f; energy bias %+.1f %%",
                      d.relativeMax, d.worstX, d.worstY, metals.relativeRmse,
                      dielectrics.relativeRmse, 100.0 * d.relativeBias);
        const bool splitSum = mode == IblMode::SplitSum;
        context.report.rows.push_back(
            {splitSum ? "Split-sum IBL (eq. 7: prefiltered cube x LUT, SH irradiance)"
                      : "Mobile IBL (prefiltered cube x EnvBRDFApprox, SH irradiance)",
             "reference IBL (eq. 6 per pixel, MIS)", metric, d.relativeRmse, "rel RMSE", where,
             "lighting pass " +
                 formatCost(median(ms[mode]), median(ms[IblMode::Reference]), "ms")});
    }
}

}  // namespace candela::report
