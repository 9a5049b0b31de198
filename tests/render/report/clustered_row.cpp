// Row: clustered light culling against brute force (every light at every pixel), as images
// and lighting-pass time: a floor lit by many small point lights at constant density.
#include <algorithm>
#include <cstdio>
#include <random>

#include "../test_scene.h"
#include "image_difference.h"
#include "median.h"
#include "report_context.h"

namespace candela::report {

using namespace candela::render;
using namespace candela::render::test;

namespace {

TestScene floorScene(size_t count, uint32_t width, uint32_t height) {
    TestScene scene;
    scene.width = width;
    scene.height = height;
    const float extent = 4.0f * std::sqrt(float(count));
    content::Material grey = lambertWhite();
    grey.specular = 0.5f;
    grey.roughnessFactor = 0.4f;
    scene.add(content::makePlane(std::max(100.0f, 2.5f * extent), 8), grey);
    scene.lookAt({0.0f, 6.0f, 20.0f}, {0.0f, 0.0f, -20.0f}, {0.0f, 1.0f, 0.0f});
    std::mt19937 rng{uint32_t(count)};
    std::uniform_real_distribution<float> x(-extent, extent), z(-2.0f * extent, 18.0f);
    std::uniform_real_distribution<float> y(0.1f, 1.0f), radius(1.0f, 3.0f);
    for (size_t i = 0; i < count; ++i)
        scene.lights.push_back(pointLight({x(rng), y(rng), z(rng)}, 500.0f, radius(rng)));
    return scene;
}

}  // namespace

void addClusteredRow(ReportContext& context) {
    const bool quick = context.budget.quick;
    const size_t lights = quick ? 64 : 1024;
    const uint32_t width = quick ? 128 : 320, height = quick ? 72 : 180;
    const uint32_t repetitions = quick ? 1 : 5;
    GpuContext& gpu = context.harness.context();
    TestScene scene = floorScene(lights, width, height);
    RendererOptions clustered, bruteForce;
    bruteForce.lightCulling = LightCulling::BruteForce;
    std::vector<double> clusteredMs, bruteForceMs;
    CapturedFrame clusteredImage, bruteForceImage;
    for (uint32_t r = 0; r < repetitions; ++r) {
        RendererStats a, b;
        clusteredImage = scene.render(gpu, clustered, &a, 2);
        bruteForceImage = scene.render(gpu, bruteForce, &b, 2);
        clusteredMs.push_back(a.lightingMs);
        bruteForceMs.push_back(b.lightingMs);
    }
    ImageDifference d =
        imageDifference(clusteredImage, bruteForceImage, [](uint32_t, uint32_t) { return true; });
    char metric[200];
    std::snprintf(metric, sizeof(metric),
                  "relative RMSE over all pixels (a floor under %zu point lights, radius 1-3 m, "
                  "%ux%u, CPU light assignment)",
                  lights, width, height);
    char where[128];
    if (d.relativeMax == 0.0) {
        std::snprintf(where, sizeof(where), "bit-identical HDR images (%zu pixels)", d.pixels);
    } else {
        std::snprintf(where, sizeof(where), "max %.2e of the mean at pixel (%u, %u)", d.relativeMax,
                      d.worstX, d.worstY);
    }
    context.report.rows.push_back(
        {"Clustered light culling",
         "brute force (every light, every "
         "pixel)",
         metric, d.relativeRmse, "rel RMSE", where,
         "lighting pass " + formatCost(median(clusteredMs), median(bruteForceMs), "ms")});
}

}  // namespace candela::report
