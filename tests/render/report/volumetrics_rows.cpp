// Rows: volumetric lighting (issue 17). Vos's (2014, GPU Pro 5, "Volumetric Light Effects in
// Killzone: Shadow Fall") per-light volumes and froxels against the per-pixel reference march at 1,
// 16, 256 and 4,096 point lights scattered through uniform fog in front of a black wall, so every
// pixel holds only the in-scattered radiance. The lights' range shrinks as they crowd (3 m up to 16
// lights, then 3 m x cbrt(16 / n): 1.19 m at 256, 0.47 m at 4,096), as a scene's many small lights
// do, so the per-light volumes' tiles (or proxy meshes: VolumetricsSettings::volumeProxies, their
// own rows) skip the lights whose volume they miss. Error: mean
// |mode - reference| over the image, relative to the reference's mean. Cost: GPU time of the
// volumetrics passes (`volumetrics_ms`, median of the repetitions), each mode against the
// reference. A note gives the light count from which froxels cost less than the volumes.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <utility>
#include <vector>

#include "../test_scene.h"
#include "candela/content/render_setting_table.h"
#include "median.h"
#include "passes/volumetrics/light_bins.h"
#include "passes/volumetrics/volumetrics_pass.h"
#include "report_context.h"

namespace candela::report {

using namespace candela::render;
using namespace candela::render::test;

namespace {

// The lights' range (m): 3 m up to 16 lights, then shrinking with the cube root of the count.
float lightRange(uint32_t lights) {
    return 3.0f * std::cbrt(16.0f / float(std::max(lights, 16u)));
}

TestScene fogScene(uint32_t width, uint32_t height, uint32_t lights) {
    TestScene scene;
    scene.width = width;
    scene.height = height;
    content::Material black = lambertWhite();
    black.baseColorFactor = {0.0f, 0.0f, 0.0f, 1.0f};
    scene.add(content::makePlane(12.0f, 1), black,
              glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -8.0f)) *
                  glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(1, 0, 0)));
    scene.lookAt(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    // A fixed low-discrepancy spread through the view (R3 sequence), the same every run.
    for (uint32_t i = 0; i < lights; ++i) {
        const float a = std::fmod(0.5f + 0.8191725f * float(i), 1.0f);
        const float b = std::fmod(0.5f + 0.6710436f * float(i), 1.0f);
        const float c = std::fmod(0.5f + 0.5497005f * float(i), 1.0f);
        scene.lights.push_back(
            pointLight(glm::vec3(-4.0f + 8.0f * a, -3.0f + 6.0f * b, -7.5f + 6.5f * c),
                       2000.0f / std::sqrt(float(lights)), lightRange(lights)));
    }
    return scene;
}

struct Rendered {
    CapturedFrame frame;
    double ms = 0.0;
    // Each volumetrics pass's GPU time (median of the repetitions), in the order they ran.
    std::vector<std::pair<std::string, double>> passes;
};

// `proxies`: the per-light volumes by their rasterised proxy meshes instead of the compute march
// over CPU light lists per tile (VolumetricsSettings::volumeProxies).
Rendered renderMode(GpuContext& gpu, TestScene& scene, const content::Fog& fog,
                    VolumetricsMode mode, uint32_t repetitions, bool proxies = false) {
    SceneResources resources(gpu);
    FrameInputs inputs = scene.prepare(resources);
    inputs.scene.fog = fog;
    RendererOptions options;
    options.volumetrics = mode;
    options.volumetricsSettings.referenceSteps = 128;
    options.volumeProxies = proxies;
    std::vector<double> ms;
    std::vector<std::pair<std::string, std::vector<double>>> passMs;
    Rendered r;
    for (uint32_t i = 0; i < repetitions; ++i) {
        RendererStats stats;
        // GPU timestamps: the frame's pipeline creation on the CPU is not in them.
        r.frame =
            renderOffscreen(gpu, inputs, scene.width, scene.height, 1, &resources, options, &stats);
        ms.push_back(stats.volumetricsMs);
        for (const auto& [name, passTime] : stats.passMs) {
            if (!name.starts_with("volumetrics_")) continue;
            auto found = std::find_if(passMs.begin(), passMs.end(),
                                      [&](const auto& p) { return p.first == name; });
            if (found == passMs.end()) found = passMs.insert(passMs.end(), {name, {}});
            found->second.push_back(passTime);
        }
    }
    r.ms = median(ms);
    for (auto& [name, times] : passMs)
        r.passes.emplace_back(name, median(times));
    return r;
}

struct Costs {
    uint32_t count;
    double volumesMs = 0.0, froxelsMs = 0.0, proxiesMs = 0.0;
    // "volumes_march 1.2 + volumes_blur ..." (ms); proxies: the volumes by proxy meshes
    std::string volumesPasses, froxelsPasses, proxiesPasses;
};

// Records a render's cost under its mode in `cost` (`proxies`: the volumes by proxy meshes).
void addCost(Costs& cost, VolumetricsMode mode, const Rendered& r, bool proxies = false) {
    (proxies                            ? cost.proxiesMs
     : mode == VolumetricsMode::Volumes ? cost.volumesMs
                                        : cost.froxelsMs) = r.ms;
    std::string& passes = proxies                            ? cost.proxiesPasses
                          : mode == VolumetricsMode::Volumes ? cost.volumesPasses
                                                             : cost.froxelsPasses;
    for (const auto& [pass, passTime] : r.passes) {
        if (!passes.empty()) passes += " + ";
        passes += pass.substr(std::string("volumetrics_").size()) + " " + formatNumber(passTime);
    }
}

// The cross-over: the smallest light count from which froxels cost less at that count and at
// every larger one measured (one count alone can flip on a loaded machine), with the costs
// and each pass's share.
std::string crossoverNote(const std::string& what, const std::vector<Costs>& costs) {
    std::string measured;
    const Costs* crossover = nullptr;
    for (const Costs& c : costs) {
        if (!measured.empty()) measured += "; ";
        measured += std::to_string(c.count) + " lights: volumes " + formatNumber(c.volumesMs) +
                    " ms (" + c.volumesPasses + "), volumes by proxy meshes " +
                    formatNumber(c.proxiesMs) + " ms (" + c.proxiesPasses + "), froxels " +
                    formatNumber(c.froxelsMs) + " ms (" + c.froxelsPasses + ")";
        if (c.froxelsMs >= c.volumesMs) {
            crossover = nullptr;
        } else if (!crossover) {
            crossover = &c;
        }
    }
    return "Volumetrics cross-over (per-light volumes of Vos 2014, GPU Pro 5, against froxels, "
           "GPU time of the volumetrics passes on this device, " +
           what + "): " +
           (crossover ? "froxels cost less from " + std::to_string(crossover->count) + " lights on"
                      : std::string("froxels do not stay cheaper from any count measured")) +
           " (" + measured + ").";
}

}  // namespace

void addVolumetricsRows(ReportContext& context) {
    const bool quick = context.budget.quick;
    const uint32_t repetitions = quick ? 1 : 3;
    GpuContext& gpu = context.harness.context();
    content::Fog fog;
    fog.scattering = 0.05f;
    fog.absorption = 0.01f;
    fog.anisotropy = 0.3f;
    const std::vector<uint32_t> counts =
        quick ? std::vector<uint32_t>{1, 16} : std::vector<uint32_t>{1, 16, 256, 4096};
    std::vector<Costs> costs;
    for (uint32_t count : counts) {
        // The reference marches every light at every step of every pixel: 4,096 lights at
        // 64x64 would take minutes a frame on lavapipe.
        const uint32_t size = quick ? 48 : count >= 4096 ? 32 : 64;
        TestScene scene = fogScene(size, size, count);
        const Rendered reference =
            renderMode(gpu, scene, fog, VolumetricsMode::Reference, repetitions);
        Costs cost{count, 0.0, 0.0};
        // The volumes twice: the tile-listed compute march (the default) and rasterised proxies.
        const std::pair<VolumetricsMode, bool> variants[] = {{VolumetricsMode::Volumes, false},
                                                             {VolumetricsMode::Volumes, true},
                                                             {VolumetricsMode::Froxels, false}};
        for (const auto& [mode, proxies] : variants) {
            const Rendered r = renderMode(gpu, scene, fog, mode, repetitions, proxies);
            addCost(cost, mode, r, proxies);
            double error = 0.0, total = 0.0, worst = 0.0;
            for (size_t i = 1; i < reference.frame.hdrRgb.size(); i += 3) {
                const double d = std::abs(double(r.frame.hdrRgb[i]) - reference.frame.hdrRgb[i]);
                error += d;
                total += reference.frame.hdrRgb[i];
                worst = std::max(worst, d);
            }
            const double pixels = double(reference.frame.hdrRgb.size() / 3);
            const glm::uvec3 grid = VolumetricsPass::froxelGrid(size, size, {});
            char name[96], metric[320], worstText[96], range[48];
            std::snprintf(range, sizeof(range), "lights' range %s m",
                          formatNumber(lightRange(count)).c_str());
            std::snprintf(name, sizeof(name), "Volumetrics: %s%s, %u point light%s",
                          candela::content::renderSettingName(mode).c_str(),
                          proxies ? " (proxy meshes)" : "", count, count == 1 ? "" : "s");
            if (mode == VolumetricsMode::Volumes) {
                std::snprintf(metric, sizeof(metric),
                              "mean |L - L_ref| / mean L_ref of the in-scattered radiance "
                              "(uniform fog 0.05 + 0.01 /m, g 0.3, black wall 8 m away, %s, %ux%u, "
                              "half resolution, %u steps per light, %s)",
                              range, size, size, RendererOptions{}.volumetricsSettings.volumeSteps,
                              proxies ? "each light's proxy mesh rasterised"
                                      : "compute march over CPU light lists per 8x8 tile");
            } else {
                std::snprintf(metric, sizeof(metric),
                              "mean |L - L_ref| / mean L_ref of the in-scattered radiance "
                              "(uniform fog 0.05 + 0.01 /m, g 0.3, black wall 8 m away, %s, %ux%u, "
                              "grid %ux%ux%u)",
                              range, size, size, grid.x, grid.y, grid.z);
            }
            std::snprintf(worstText, sizeof(worstText), "worst pixel %s of the mean",
                          formatNumber(total > 0.0 ? worst / (total / pixels) : 0.0).c_str());
            context.report.rows.push_back({name, "per-pixel march, 128 steps, every light", metric,
                                           total > 0.0 ? error / total : 0.0, "rel", worstText,
                                           "volumetrics " + formatCost(r.ms, reference.ms, "ms")});
        }
        costs.push_back(cost);
    }
    // The 4,096-light rows render at 32x32, so their costs compare with each other, not with
    // the 64x64 rows.
    context.report.notes.push_back(crossoverNote("the rows' images", costs));
    // Cost alone at 320x180 (no reference), where the froxel grid (40x23x64) and the march
    // tiles (20x12) are fine enough for their lists to cull as at full size.
    if (!quick) {
        std::vector<Costs> wide;
        for (uint32_t count : counts) {
            TestScene scene = fogScene(320, 180, count);
            Costs cost{count};
            for (VolumetricsMode mode : {VolumetricsMode::Volumes, VolumetricsMode::Froxels})
                addCost(cost, mode, renderMode(gpu, scene, fog, mode, repetitions));
            addCost(cost, VolumetricsMode::Volumes,
                    renderMode(gpu, scene, fog, VolumetricsMode::Volumes, repetitions, true), true);
            wide.push_back(cost);
        }
        context.report.notes.push_back(crossoverNote("320x180, the rows' scenes", wide));
    }
    // The CPU side of the light lists (light_bins.h): 4,096 lights at 1280x720 (tiles of the
    // march, clusters of the 160x90x64 grid), median of 5.
    TestScene many = fogScene(1280, 720, 4096);
    const std::vector<float> scales(many.lights.size(), 1.0f);
    std::vector<double> volumeBinMs, froxelBinMs;
    size_t volumeEntries = 0, froxelEntries = 0;
    for (int i = 0; i < 5; ++i) {
        using Clock = std::chrono::steady_clock;
        const auto start = Clock::now();
        volumeEntries =
            binLights(many.lights, scales, many.camera, volumeTileLayout(1280, 720)).size();
        const auto middle = Clock::now();
        froxelEntries = binLights(many.lights, scales, many.camera,
                                  froxelClusterLayout(VolumetricsPass::froxelGrid(1280, 720, {}),
                                                      0.05f, 100.0f))
                            .size();
        const auto end = Clock::now();
        volumeBinMs.push_back(std::chrono::duration<double, std::milli>(middle - start).count());
        froxelBinMs.push_back(std::chrono::duration<double, std::milli>(end - middle).count());
    }
    context.report.notes.push_back(
        "Volumetrics light lists (CPU, per frame, 4,096 lights at 1280x720): march tiles " +
        formatNumber(median(volumeBinMs)) + " ms (" + std::to_string(volumeEntries) +
        " words), froxel clusters " + formatNumber(median(froxelBinMs)) + " ms (" +
        std::to_string(froxelEntries) + " words).");
}

}  // namespace candela::report
