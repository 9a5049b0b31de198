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
#include "../test_scene.h"
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

namespace {

// A texture of hashed bytes: every texel differs, so each fetch costs what a real one does.
content::Rgba8Image noiseImage(uint32_t size, uint32_t seed) {
    content::Rgba8Image image;
    image.width = image.height = size;
    image.rgba.resize(size_t(size) * size * 4);
    for (size_t i = 0; i < image.rgba.size(); ++i) {
        uint32_t h = uint32_t(i) * 2654435761u + seed * 40503u;
        h ^= h >> 15;
        image.rgba[i] = uint8_t(h * 2246822519u >> 24);
    }
    return image;
}

// Cost per material layer (issue 21): the G-buffer pass over a full-screen plane whose material
// has 1 to 4 layers, each with base colour, metallic-roughness and normal textures at its own UV
// scale, and a mask giving every layer weight 0.5 (so none is skipped). One layer is the base
// alone (the unlayered variant); 2 to 4 use the layered variant. The lighting pass is timed too:
// the layers blend before lighting, so it should not change with the count.
void addMaterialLayerRows(ReportContext& context) {
    const bool quick = context.budget.quick;
    GpuContext& gpu = context.harness.context();
    const uint32_t size = quick ? 128 : 512;
    const uint32_t repetitions = quick ? 3 : 9;
    test::TestScene scene;
    scene.width = scene.height = size;
    content::Model& model = scene.model;
    content::Rgba8Image mask;
    mask.width = mask.height = 4;
    mask.rgba.assign(4 * 4 * 4, 128);
    model.images.push_back(mask);
    for (uint32_t i = 0; i < 12; ++i)
        model.images.push_back(noiseImage(256, i + 1));
    for (uint32_t i = 0; i < model.images.size(); ++i)
        model.textures.push_back({"", int32_t(i), {}});
    scene.add(content::makePlane(2.0f), content::Material{});
    scene.lookAt({0.0f, 1.2f, 0.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f});
    LightInstance sun;
    sun.light.type = content::LightType::Directional;
    sun.light.lux = 3.0f;
    sun.direction = glm::normalize(glm::vec3(-0.3f, -1.0f, -0.2f));
    scene.lights.push_back(sun);

    auto layered = [](uint32_t count) {
        content::Material m;
        for (uint32_t i = 0; i < count; ++i) {
            content::MaterialLayer l;
            l.name = "layer " + std::to_string(i);
            l.baseColorFactor = {0.2f + 0.2f * float(i), 0.5f, 0.8f - 0.2f * float(i), 1.0f};
            l.roughnessFactor = 0.3f + 0.2f * float(i);
            l.baseColorTexture.texture = int32_t(1 + 3 * i);
            l.metallicRoughnessTexture.texture = int32_t(2 + 3 * i);
            l.normalTexture.texture = int32_t(3 + 3 * i);
            l.uvScale = {1.0f + 3.0f * float(i), 1.0f + 3.0f * float(i)};
            m.layering.layers.push_back(l);
        }
        m.layering.maskTexture.texture = 0;
        return m;
    };
    std::map<uint32_t, std::vector<double>> gbufferMs, lightingMs;
    for (uint32_t r = 0; r < repetitions; ++r) {
        for (uint32_t count = 1; count <= content::kMaxMaterialLayers; ++count) {
            scene.model.materials[0] = layered(count);
            RendererStats stats;
            scene.render(gpu, RendererOptions{}, &stats, 2);
            for (const auto& [name, ms] : stats.passMs) {
                if (name == "gbuffer") gbufferMs[count].push_back(ms);
            }
            lightingMs[count].push_back(stats.lightingMs);
        }
    }
    const double base = median(gbufferMs[1]);
    const double baseLighting = median(lightingMs[1]);
    for (uint32_t count = 2; count <= content::kMaxMaterialLayers; ++count) {
        const double ms = median(gbufferMs[count]);
        const double lighting = median(lightingMs[count]);
        char approximation[160];
        std::snprintf(approximation, sizeof(approximation),
                      "Material layers: %u layers blended in the G-buffer pass (mask texture, 3 "
                      "textures per layer)",
                      count);
        char metric[240];
        std::snprintf(metric, sizeof(metric),
                      "lighting pass time with %u layers against 1 (relative change; the blend "
                      "is exact, MaterialLayers test); %ux%u full-screen plane, median of %u",
                      count, size, size, repetitions);
        char where[200];
        std::snprintf(where, sizeof(where),
                      "G-buffer pass +%.2f ms per extra layer; lighting pass %.2f vs %.2f ms",
                      (ms - base) / double(count - 1), lighting, baseLighting);
        context.report.rows.push_back(
            {approximation, "1 layer (the base alone, unlayered G-buffer variant)", metric,
             baseLighting > 0.0 ? lighting / baseLighting - 1.0 : 0.0, "rel", where,
             "G-buffer pass " + formatCost(ms, base, "ms")});
    }
}

}  // namespace

void addMaterialRows(ReportContext& context) {
    addMaterialLayerRows(context);
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
