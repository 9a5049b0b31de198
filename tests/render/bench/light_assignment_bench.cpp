// candela-bench-light-assignment: the CPU light assignment alone (no GPU), on the light
// culling benchmark's floor with an analytic depth buffer, with and without the frustum
// pre-pass and with and without the quarter masks, alternating in the same process. Prints a
// markdown table of medians; it measures, it never fails on a number.
//
//   build/bin/candela-bench-light-assignment [--size WxH] [--rounds N] [--calls N]
//                                            [--max-lights N] [--workers N] [--efficiency]
//
// Each round times `calls` warm calls per mode (pre-pass off, pre-pass on, pre-pass on without
// quarter masks) and keeps their median; the table gives the median over rounds and the
// median of the per-round ratios. The checksum is of the lists with both on.
// --workers: job-system worker threads (default: one per core beyond the caller's; 0 runs the
// assignment on the calling thread alone, steadier on a loaded machine).
// --efficiency instead prints evaluated / lit pairs of the CPU lists on the floor and the
// mixed-size floor, with the exact per-cluster and per-8-px bounds (list_efficiency.h).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "analytic_floor.h"
#include "candela/ecs/job_system.h"
#include "list_efficiency.h"
#include "median.h"

using namespace candela::render;
using namespace candela::render::bench;
using candela::median;

namespace {

// FNV-1a over the lists and ranges: equal across builds when a change keeps the lists.
uint64_t listChecksum(const LightAssignment& a, const std::vector<uint32_t>& ranges) {
    uint64_t h = 1469598103934665603ull;
    auto add = [&](uint32_t v) {
        for (int b = 0; b < 4; ++b)
            h = (h ^ ((v >> (8 * b)) & 0xffu)) * 1099511628211ull;
    };
    for (uint32_t v : a.lightIndices)
        add(v);
    for (uint32_t v : ranges)
        add(v);
    return h;
}

void printEfficiency(candela::ecs::JobSystem& jobs) {
    std::printf(
        "| scene | size | lights | evaluated / lit (CPU lists) | lists without quarter masks | "
        "exact per 16 px cluster | 8 px quarter planes | 8 px quarter boxes | exact per 8 px "
        "quarter |\n|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
    enum class Scene { Floor, TestFloor, Mixed };
    struct Case {
        Scene scene;
        uint32_t width, height;
        size_t lights;
    };
    const Case cases[] = {{Scene::Floor, 640, 360, 1024},      {Scene::Floor, 1280, 720, 1024},
                          {Scene::Floor, 1280, 720, 65536},    {Scene::TestFloor, 640, 360, 1024},
                          {Scene::TestFloor, 1280, 720, 1024}, {Scene::Mixed, 640, 360, 1024},
                          {Scene::Mixed, 1280, 720, 1024}};
    for (const Case& c : cases) {
        // TestFloor: the same lights on the 100 m plane of CullingEfficiencyOnAFloor.
        const float halfExtent = c.scene == Scene::Mixed       ? kMixedSizeFloorHalfExtent
                                 : c.scene == Scene::TestFloor ? 100.0f
                                                               : floorHalfExtent(c.lights);
        const char* name = c.scene == Scene::Mixed       ? "mixed sizes"
                           : c.scene == Scene::TestFloor ? "floor, 100 m plane"
                                                         : "floor";
        const AnalyticFloorView floor = analyticFloorView(c.width, c.height, halfExtent);
        const std::vector<LightInstance> lights =
            c.scene == Scene::Mixed ? mixedSizeLights(c.lights) : floorLights(c.lights);
        std::vector<uint32_t> ranges(size_t(floor.grid.clusterCount()) * 2, 0);
        LightAssignment assignment;
        assignLights(floor.grid, lights, floor.view, floor.occupancy(), &jobs, ranges, assignment);
        const ListEfficiency e = listEfficiency(floor, lights, assignment, ranges);
        std::printf("| %s | %ux%u | %zu | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f |\n", name,
                    c.width, c.height, c.lights, e.lists, e.listsUnmasked, e.exactPerCluster,
                    e.quarterPlanes, e.quarterBoxes, e.exactPerSubTile);
        std::fflush(stdout);
    }
}

}  // namespace

int main(int argc, char** argv) {
    uint32_t width = 1280, height = 720, rounds = 5, calls = 7;
    size_t maxLights = 65536;
    unsigned workers = candela::ecs::JobSystem::defaultWorkerCount();
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!std::strcmp(argv[i], "--size")) std::sscanf(argv[i + 1], "%ux%u", &width, &height);
        if (!std::strcmp(argv[i], "--rounds"))
            rounds = std::max(1u, uint32_t(std::strtoul(argv[i + 1], nullptr, 10)));
        if (!std::strcmp(argv[i], "--calls"))
            calls = std::max(1u, uint32_t(std::strtoul(argv[i + 1], nullptr, 10)));
        if (!std::strcmp(argv[i], "--max-lights"))
            maxLights = std::strtoull(argv[i + 1], nullptr, 10);
        if (!std::strcmp(argv[i], "--workers"))
            workers = unsigned(std::strtoul(argv[i + 1], nullptr, 10));
    }
    candela::ecs::JobSystem jobs(workers);
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--efficiency")) {
            printEfficiency(jobs);
            return 0;
        }
    }
    std::printf("CPU light assignment, %ux%u, %u job threads, medians of %u rounds x %u calls\n\n",
                width, height, jobs.threadCount(), rounds, calls);
    std::printf(
        "| lights | in frustum | pairs | without pre-pass ms | with pre-pass ms | with / without "
        "| without quarter masks ms | masks: with / without | list checksum "
        "|\n|---:|---:|---:|---:|---:|---:|---:|---:|---|\n");
    for (size_t count = 1024; count <= maxLights; count *= 4) {
        const AnalyticFloorView floor = analyticFloorView(width, height, floorHalfExtent(count));
        const std::vector<LightInstance> lights = floorLights(count);
        std::vector<uint32_t> ranges(size_t(floor.grid.clusterCount()) * 2, 0);
        LightAssignment assignment;
        std::vector<double> without, with, ratio, unmasked, maskRatio;
        for (uint32_t r = 0; r < rounds; ++r) {
            double perMode[3];
            // Modes: pre-pass off, unmasked, both on (last, so the checksum is of those lists).
            for (int mode : {0, 2, 1}) {
                assignment.frustumPrepass = mode != 0;
                assignment.quarterMasks = mode != 2;
                std::vector<double> times;
                for (uint32_t c = 0; c <= calls; ++c) {  // the first call warms the scratch
                    auto start = std::chrono::steady_clock::now();
                    assignLights(floor.grid, lights, floor.view, floor.occupancy(), &jobs, ranges,
                                 assignment);
                    auto end = std::chrono::steady_clock::now();
                    if (c > 0) {
                        times.push_back(
                            std::chrono::duration<double, std::milli>(end - start).count());
                    }
                }
                perMode[mode] = median(times);
            }
            without.push_back(perMode[0]);
            with.push_back(perMode[1]);
            ratio.push_back(perMode[1] / std::max(perMode[0], 1e-9));
            unmasked.push_back(perMode[2]);
            maskRatio.push_back(perMode[1] / std::max(perMode[2], 1e-9));
        }
        std::printf("| %zu | %u | %u | %.3f | %.3f | %.2f | %.3f | %.2f | %016llx |\n", count,
                    assignment.lightsInFrustum, assignment.assignedPairs, median(without),
                    median(with), median(ratio), median(unmasked), median(maskRatio),
                    (unsigned long long)listChecksum(assignment, ranges));
        std::fflush(stdout);
    }
    return 0;
}
