// Rows: levels of detail (render/README.md "Culling and levels of detail"). A 5x5 grid of
// 9,216-triangle spheres (metal and dielectric, roughness 0.1 to 1) on a floor under a sun
// that casts, 128x128: each view drawing every mesh at the coarsest level within 0.25, 0.5 or
// 1 pixel (shadow maps: texels) against the full meshes (--lod-error 0), with the triangles
// drawn and the G-buffer's and shadow maps' GPU times.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <string>
#include <vector>

#include "../offscreen_frame.h"
#include "../test_scene.h"
#include "candela/content/procedural_mesh.h"
#include "median.h"
#include "report_context.h"

namespace candela::report {

using namespace candela::render;
using namespace candela::render::test;

namespace {

TestScene sphereGrid(uint32_t size) {
    TestScene scene;
    scene.width = scene.height = size;
    scene.add(content::makePlane(6.0f, 4), lambertWhite());
    for (int row = 0; row < 5; ++row) {
        for (int column = 0; column < 5; ++column) {
            content::Material m;
            m.baseColorFactor = row % 2 ? std::array<float, 4>{0.95f, 0.64f, 0.54f, 1.0f}
                                        : std::array<float, 4>{0.2f, 0.4f, 0.8f, 1.0f};
            m.metallicFactor = row % 2 ? 1.0f : 0.0f;
            m.roughnessFactor = 0.1f + 0.225f * float(column);
            scene.add(content::makeSphere(0.3f, 96, 48), m,
                      glm::translate(glm::mat4(1.0f),
                                     glm::vec3(float(column - 2), 0.3f, float(row - 2))));
        }
    }
    scene.lookAt({0.0f, 3.5f, 5.5f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f});
    LightInstance sun;
    sun.light.type = content::LightType::Directional;
    sun.light.lux = 5.0f;
    sun.light.castShadows = true;
    sun.direction = glm::normalize(glm::vec3(0.4f, -1.0f, -0.3f));
    LightInstance lamp = pointLight({1.5f, 2.0f, 1.5f}, 3000.0f, 8.0f);
    lamp.light.castShadows = true;
    scene.lights = {sun, lamp};
    return scene;
}

struct LodRun {
    CapturedFrame frame;
    uint64_t triangles = 0, shadowTriangles = 0;
    double gbufferMs = 0.0, shadowsMs = 0.0;
};

LodRun run(GpuContext& gpu, float pixelError, uint32_t size, uint32_t repetitions) {
    RendererOptions options;
    options.lodPixelError = pixelError;
    options.shadowCache = false;  // every frame renders its maps: their time is measured
    TestScene scene = sphereGrid(size);
    SceneResources resources(gpu);
    FrameInputs inputs = scene.prepare(resources);
    FrameSequence frames(gpu, size, size, options);
    LodRun out;
    std::map<std::string, std::vector<double>> ms;
    for (uint32_t r = 0; r < repetitions + 1; ++r) {
        RendererStats stats;
        out.frame = frames.render(inputs, resources, &stats);
        out.triangles = stats.work.triangles;
        out.shadowTriangles = stats.work.shadowTriangles;
        if (r == 0) continue;  // pipelines
        for (const auto& [name, t] : stats.passMs)
            ms[name].push_back(t);
    }
    out.gbufferMs = ms["gbuffer"].empty() ? 0.0 : median(ms["gbuffer"]);
    out.shadowsMs = ms["shadows"].empty() ? 0.0 : median(ms["shadows"]);
    return out;
}

// The issue-41 image error: sum |Y - Y_reference| / sum Y_reference over the HDR image (an
// L1 error a few bright highlights cannot dominate), and the pixel that differs most.
struct LuminanceError {
    double relative = 0.0;
    uint32_t worstX = 0, worstY = 0;
    double worstShare = 0.0;  // that pixel's |difference| / the reference's mean luminance
};
LuminanceError luminanceError(const CapturedFrame& a, const CapturedFrame& reference) {
    LuminanceError e;
    double difference = 0.0, total = 0.0, worst = 0.0;
    const auto luminance = [](const float* rgb) {
        return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
    };
    for (uint32_t y = 0; y < reference.height; ++y) {
        for (uint32_t x = 0; x < reference.width; ++x) {
            const size_t i = (size_t(y) * reference.width + x) * 3;
            const double d = std::abs(luminance(&a.hdrRgb[i]) - luminance(&reference.hdrRgb[i]));
            difference += d;
            total += luminance(&reference.hdrRgb[i]);
            if (d > worst) {
                worst = d;
                e.worstX = x;
                e.worstY = y;
            }
        }
    }
    e.relative = total > 0.0 ? difference / total : 0.0;
    const double mean = total / double(std::max<size_t>(reference.hdrRgb.size() / 3, 1));
    e.worstShare = mean > 0.0 ? worst / mean : 0.0;
    return e;
}

}  // namespace

void addLevelOfDetailRows(ReportContext& context) {
    const uint32_t size = 128;
    const uint32_t repetitions = context.budget.quick ? 2 : 9;
    GpuContext& gpu = context.harness.context();
    const LodRun full = run(gpu, 0.0f, size, repetitions);
    for (float pixels : {0.25f, 0.5f, 1.0f}) {
        const LodRun lod = run(gpu, pixels, size, repetitions);
        const LuminanceError e = luminanceError(lod.frame, full.frame);
        char name[96], metric[200], where[160], cost[240];
        std::snprintf(name, sizeof(name), "Levels of detail within %.2f px (--lod-error %.2f)",
                      pixels, pixels);
        std::snprintf(
            metric, sizeof(metric),
            "relative L1 luminance error of the HDR image, a 5x5 grid of 9,216-triangle spheres "
            "(roughness 0.1..1) on a floor, a casting sun and point light, %ux%u",
            size, size);
        std::snprintf(where, sizeof(where), "worst pixel %u,%u (%.2f x the mean luminance)",
                      e.worstX, e.worstY, e.worstShare);
        std::snprintf(cost, sizeof(cost),
                      "triangles %llu vs %llu, in shadow maps %llu vs %llu; G-buffer %.2f vs "
                      "%.2f ms, shadow maps %.2f vs %.2f ms",
                      (unsigned long long)lod.triangles, (unsigned long long)full.triangles,
                      (unsigned long long)lod.shadowTriangles,
                      (unsigned long long)full.shadowTriangles, lod.gbufferMs, full.gbufferMs,
                      lod.shadowsMs, full.shadowsMs);
        context.report.rows.push_back(
            {name, "full meshes (--lod-error 0)", metric, e.relative, "rel", where, cost});
    }
}

}  // namespace candela::report
