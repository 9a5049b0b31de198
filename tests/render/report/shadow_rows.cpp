// Rows: shadows (issue 14) against a CPU ray-traced reference of the same scene. PCF under a
// point light (one ray per pixel), the penumbra filter under a 0.2 m sphere light (256 rays to
// the light's disk per pixel), and 2, 3 and 4 sun cascades over a field of boxes. Error: the
// mean absolute difference of the light's visibility (rendered: shadowed / unshadowed
// radiance) over the floor pixels the light reaches; the cascades also count the pixels on the
// wrong side of one half. Cost: shadow pass + lighting pass against lighting without shadows.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>

#include "../shadow_reference.h"
#include "../test_scene.h"
#include "median.h"
#include "report_context.h"

namespace candela::report {

using namespace candela::render;
using namespace candela::render::test;

namespace {

struct ShadowScene {
    TestScene scene;
    std::vector<Box> boxes;
};

void addBox(ShadowScene& s, const Box& b) {
    const glm::vec3 half = 0.5f * (b.hi - b.lo);
    s.scene.add(content::makeBox({half.x, half.y, half.z}), lambertWhite(),
                glm::translate(glm::mat4(1.0f), 0.5f * (b.lo + b.hi)));
    s.boxes.push_back(b);
}

struct Measured {
    double meanError = 0.0;      // mean |V - V_reference|
    double misclassified = 0.0;  // share of pixels on the wrong side of V = 0.5
    size_t pixels = 0;
    double shadowMs = 0.0, lightingMs = 0.0, plainLightingMs = 0.0;
};

// Renders the scene with its one light casting and not, and compares the visibility with
// `reference(p)` on the floor pixels the light reaches.
template <class Reference>
Measured measure(GpuContext& context, ShadowScene& s, const RendererOptions& options,
                 uint32_t repetitions, Reference reference) {
    std::vector<double> shadowMs, lightingMs, plainMs;
    CapturedFrame shadowed, plain;
    for (uint32_t r = 0; r < repetitions; ++r) {
        RendererStats on, off;
        RendererOptions uncached = options;
        uncached.shadowCache = false;  // every frame renders its maps: what they cost
        s.scene.lights[0].light.castShadows = true;
        shadowed = s.scene.render(context, uncached, &on, 2);
        s.scene.lights[0].light.castShadows = false;
        plain = s.scene.render(context, uncached, &off, 2);
        shadowMs.push_back(on.shadowMs);
        lightingMs.push_back(on.lightingMs);
        plainMs.push_back(off.lightingMs);
    }
    float brightest = 0.0f;
    for (size_t i = 1; i < plain.hdrRgb.size(); i += 3)
        brightest = std::max(brightest, plain.hdrRgb[i]);
    Measured m;
    for (uint32_t y = 0; y < s.scene.height; ++y) {
        for (uint32_t x = 0; x < s.scene.width; ++x) {
            const std::optional<glm::vec3> p = s.scene.pixelOnPlane(x, y);
            if (!p || segmentHitsAny(s.scene.camera.position, *p, s.boxes)) continue;
            const float unshadowed = hdrPixel(plain, x, y)[1];
            if (unshadowed < 1e-3f * brightest) continue;
            const double v = std::clamp(hdrPixel(shadowed, x, y)[1] / unshadowed, 0.0f, 1.0f);
            const double truth = reference(*p);
            m.meanError += std::abs(v - truth);
            m.misclassified += (v < 0.5) != (truth < 0.5) ? 1.0 : 0.0;
            ++m.pixels;
        }
    }
    m.meanError /= double(std::max<size_t>(m.pixels, 1));
    m.misclassified /= double(std::max<size_t>(m.pixels, 1));
    m.shadowMs = median(shadowMs);
    m.lightingMs = median(lightingMs);
    m.plainLightingMs = median(plainMs);
    return m;
}

std::string costOf(const Measured& m) {
    return "shadows + lighting " + formatCost(m.shadowMs + m.lightingMs, m.plainLightingMs, "ms") +
           " vs lighting without shadows";
}

// A box over a floor under a light 2.4 m up, seen from above.
ShadowScene boxOverFloor(uint32_t size) {
    ShadowScene s;
    s.scene.width = s.scene.height = size;
    s.scene.add(content::makePlane(8.0f, 4), lambertWhite());
    addBox(s, {{-0.5f, 0.6f, -0.5f}, {0.5f, 1.2f, 0.5f}});
    s.scene.lookAt({0.0f, 5.0f, 3.5f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f});
    return s;
}

}  // namespace

void addShadowRows(ReportContext& context) {
    const bool quick = context.budget.quick;
    const uint32_t size = quick ? 96 : 256;
    const uint32_t repetitions = quick ? 1 : 5;
    const int raysPerPixel = quick ? 32 : 256;
    GpuContext& gpu = context.harness.context();
    char metric[256];

    {
        ShadowScene s = boxOverFloor(size);
        const glm::vec3 light(-0.7f, 2.4f, 0.4f);
        s.scene.lights = {pointLight(light, 2000.0f, 20.0f)};
        const Measured m = measure(gpu, s, {}, repetitions, [&](const glm::vec3& p) {
            return segmentHitsAny(p, light, s.boxes) ? 0.0 : 1.0;
        });
        std::snprintf(metric, sizeof(metric),
                      "mean |visibility - reference| over %zu floor pixels (box over a floor, "
                      "point light, cube map 256 per face, %ux%u)",
                      m.pixels, size, size);
        context.report.rows.push_back(
            {"Shadows: PCF, 2x2 comparison-sampler taps (point light)",
             "CPU ray cast, one ray per pixel", metric, m.meanError, "abs",
             formatNumber(100.0 * m.misclassified) + "% of pixels on the wrong side of 0.5",
             costOf(m)});
    }
    {
        ShadowScene s = boxOverFloor(size);
        const glm::vec3 light(-0.7f, 2.4f, 0.4f);
        s.scene.lights = {pointLight(light, 2000.0f, 20.0f)};
        s.scene.lights[0].light.sourceRadius = 0.2f;
        const Measured m = measure(gpu, s, {}, repetitions, [&](const glm::vec3& p) {
            return double(sphereLightVisibility(p, light, 0.2f, s.boxes, raysPerPixel));
        });
        std::snprintf(metric, sizeof(metric),
                      "mean |visibility - reference| over %zu floor pixels (box over a floor, "
                      "sphere light r = 0.2 m, %ux%u)",
                      m.pixels, size, size);
        char reference[96];
        std::snprintf(reference, sizeof(reference),
                      "CPU ray trace, %d rays to the light's disk per pixel", raysPerPixel);
        context.report.rows.push_back(
            {"Shadows: blocker search + penumbra filter (sphere light)", reference, metric,
             m.meanError, "abs",
             formatNumber(100.0 * m.misclassified) + "% of pixels on the wrong side of 0.5",
             costOf(m)});
    }
    for (uint32_t cascades : {2u, 3u, 4u}) {
        // A 6 x 6 field of boxes under a low sun, seen across to 30 m.
        ShadowScene s;
        s.scene.width = quick ? 128 : 320;
        s.scene.height = quick ? 72 : 180;
        s.scene.add(content::makePlane(40.0f, 8), lambertWhite());
        for (int z = 0; z < 6; ++z) {
            for (int x = 0; x < 6; ++x) {
                const glm::vec3 c(-12.5f + 5.0f * float(x), 0.0f, -27.5f + 5.0f * float(z));
                addBox(s, {c + glm::vec3(-0.5f, 0.0f, -0.5f), c + glm::vec3(0.5f, 1.5f, 0.5f)});
            }
        }
        s.scene.lookAt({0.0f, 3.0f, 4.0f}, {0.0f, 0.0f, -12.0f}, {0.0f, 1.0f, 0.0f});
        LightInstance sun;
        sun.light.type = content::LightType::Directional;
        sun.light.lux = 10.0f;
        sun.direction = glm::normalize(glm::vec3(0.5f, -0.6f, 0.3f));
        s.scene.lights = {sun};
        RendererOptions options;
        options.shadowCascades = cascades;
        options.shadowDistance = 30.0f;
        const Measured m = measure(gpu, s, options, repetitions, [&](const glm::vec3& p) {
            return segmentHitsAny(p, p - sun.direction * 100.0f, s.boxes) ? 0.0 : 1.0;
        });
        std::snprintf(metric, sizeof(metric),
                      "mean |visibility - reference| over %zu floor pixels (36 boxes under a "
                      "sun, 1024² per cascade over 30 m, %ux%u)",
                      m.pixels, s.scene.width, s.scene.height);
        char name[64];
        std::snprintf(name, sizeof(name), "Shadows: %u sun cascades (PCF)", cascades);
        context.report.rows.push_back(
            {name, "CPU ray cast toward the sun", metric, m.meanError, "abs",
             formatNumber(100.0 * m.misclassified) + "% of pixels on the wrong side of 0.5",
             costOf(m)});
    }
}

}  // namespace candela::report
