// candela-bench-lights: clustered light culling against brute force, swept over light counts
// on one scene family (a floor whose lights keep a constant density, so each pixel is touched
// by a bounded number of lights however many the scene holds), with light assignment on the
// CPU (job system) and in compute shaders, alternating in the same process. Prints a markdown
// table; it measures, it never fails on a number.
//
//   build/bin/candela-bench-lights [--size WxH] [--max-lights N] [--brute-force-max N]
//                                  [--repeat N] [--frames N] [--scene floor|mixed|test]
//
// --scene mixed: issue 22's mixed-size floor (a fixed floor patch, radii 1-3 m at 0.1-1.5 m)
// instead of the constant-density floor; --scene test: the floor's lights on the fixed 100 m
// plane of the CullingEfficiencyOnAFloor test.
// --frames: frames each renderer draws; the last is timed (default 2: warm pipelines and
// buffers; 1 times a fresh renderer's first frame, as the benchmark did before).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "../test_scene.h"
#include "analytic_floor.h"

using namespace candela::render;
using namespace candela::render::test;
using namespace candela::render::bench;

namespace {

struct Row {
    size_t lights;
    double cpuAssignMs;
    double gpuAssignMs;
    double assignRatio;  // median of the per-repetition GPU / CPU ratios
    double cpuLightingMs;
    double gpuLightingMs;
    double efficiency;
    double bruteForceMs;  // < 0: not measured
};

// Both scenes are shared with candela-bench-light-assignment (analytic_floor.h).
TestScene floorScene(size_t count, uint32_t width, uint32_t height, bool mixedSizes,
                     bool testFloor) {
    TestScene scene;
    scene.width = width;
    scene.height = height;
    scene.add(candela::content::makePlane(mixedSizes  ? kMixedSizeFloorHalfExtent
                                          : testFloor ? 100.0f
                                                      : floorHalfExtent(count),
                                          8),
              lambertWhite());
    scene.lookAt({0.0f, 6.0f, 20.0f}, {0.0f, 0.0f, -20.0f}, {0.0f, 1.0f, 0.0f});
    scene.lights = mixedSizes ? mixedSizeLights(count) : floorLights(count);
    return scene;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    uint32_t width = 1280, height = 720, repeat = 3, frames = 2;
    size_t maxLights = 65536, bruteForceMax = 1024;
    bool mixedSizes = false, testFloor = false;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!std::strcmp(argv[i], "--size")) std::sscanf(argv[i + 1], "%ux%u", &width, &height);
        if (!std::strcmp(argv[i], "--max-lights"))
            maxLights = std::strtoull(argv[i + 1], nullptr, 10);
        if (!std::strcmp(argv[i], "--brute-force-max")) {
            bruteForceMax = std::strtoull(argv[i + 1], nullptr, 10);
        }
        if (!std::strcmp(argv[i], "--repeat"))
            repeat = uint32_t(std::strtoul(argv[i + 1], nullptr, 10));
        if (!std::strcmp(argv[i], "--scene")) {
            mixedSizes = !std::strcmp(argv[i + 1], "mixed");
            testFloor = !std::strcmp(argv[i + 1], "test");
        }
        if (!std::strcmp(argv[i], "--frames")) {
            frames = std::max(1u, uint32_t(std::strtoul(argv[i + 1], nullptr, 10)));
        }
    }
    GpuContextOptions contextOptions;
    contextOptions.validation = ValidationMode::Off;  // timing run
    GpuContext context(contextOptions);
    std::printf("device: %s, %s, %ux%u, medians of %u repetitions, frame %u of each\n\n",
                context.deviceName().c_str(),
                mixedSizes  ? "mixed-size floor"
                : testFloor ? "test floor"
                            : "floor",
                width, height, repeat, frames);
    std::printf(
        "| lights | CPU assign ms | GPU assign ms | GPU / CPU | lighting ms (CPU lists) | "
        "lighting ms (GPU lists) | evaluated / lit | brute-force lighting ms |\n");
    std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (size_t count = 16; count <= maxLights; count *= 4) {
        TestScene scene = floorScene(count, width, height, mixedSizes, testFloor);
        Row row{count, 0, 0, 0, 0, 0, 0, -1};
        std::vector<double> cpuAssign, gpuAssign, ratio, cpuLighting, gpuLighting, brute;
        RendererOptions cpu, gpu;  // timing without pair counters
        cpu.lightAssignment = LightAssignmentDevice::Cpu;
        gpu.lightAssignment = LightAssignmentDevice::Gpu;
        for (uint32_t r = 0; r < repeat; ++r) {
            RendererStats cpuStats, gpuStats;
            scene.render(context, cpu, &cpuStats, frames);
            scene.render(context, gpu, &gpuStats, frames);
            if (gpuStats.lightListOverflows) std::fprintf(stderr, "GPU list overflow\n");
            cpuAssign.push_back(cpuStats.lightAssignMs);
            gpuAssign.push_back(gpuStats.lightAssignMs);
            ratio.push_back(gpuStats.lightAssignMs / std::max(cpuStats.lightAssignMs, 1e-9));
            cpuLighting.push_back(cpuStats.lightingMs);
            gpuLighting.push_back(gpuStats.lightingMs);
        }
        RendererOptions counting;
        counting.countLightPairs = true;
        RendererStats counted;
        scene.render(context, counting, &counted);
        row.efficiency =
            double(counted.lightEvaluations) / double(std::max<uint64_t>(counted.litPairs, 1));
        if (count <= bruteForceMax) {
            RendererOptions bruteForce;
            bruteForce.lightCulling = LightCulling::BruteForce;
            for (uint32_t r = 0; r < repeat; ++r) {
                RendererStats stats;
                scene.render(context, bruteForce, &stats);
                brute.push_back(stats.lightingMs);
            }
            row.bruteForceMs = median(brute);
        }
        row.cpuAssignMs = median(cpuAssign);
        row.gpuAssignMs = median(gpuAssign);
        row.assignRatio = median(ratio);
        row.cpuLightingMs = median(cpuLighting);
        row.gpuLightingMs = median(gpuLighting);
        char bruteText[32] = "not run";
        if (row.bruteForceMs >= 0)
            std::snprintf(bruteText, sizeof(bruteText), "%.1f", row.bruteForceMs);
        std::printf("| %zu | %.2f | %.2f | %.2f | %.1f | %.1f | %.2f | %s |\n", row.lights,
                    row.cpuAssignMs, row.gpuAssignMs, row.assignRatio, row.cpuLightingMs,
                    row.gpuLightingMs, row.efficiency, bruteText);
        std::fflush(stdout);
    }
    return 0;
}
