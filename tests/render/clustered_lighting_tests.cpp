// Clustered light culling against the brute-force reference (issue 5): the same image within
// 1e-4 relative on 16, 1,024 and 16,384 lights including the hard placements, and culling
// efficiency (evaluated / lit light-pixel pairs) on a floor scene.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "bench/analytic_floor.h"
#include "test_scene.h"

using namespace candela::render;
using namespace candela::render::test;
using candela::content::LightType;

namespace {

// A floor, a row of boxes and spheres to give the depth buffer some structure, seen from a
// camera 3 m up looking down the room.
TestScene roomScene(uint32_t size) {
    TestScene scene;
    scene.width = size;
    scene.height = size;
    candela::content::Material grey = lambertWhite();
    grey.specular = 0.5f;
    grey.roughnessFactor = 0.4f;
    scene.add(candela::content::makePlane(60.0f, 4), grey);
    for (int i = 0; i < 6; ++i) {
        glm::mat4 world =
            glm::translate(glm::mat4(1.0f), glm::vec3(-6.0f + 2.4f * float(i), 0.6f, -8.0f));
        scene.add(i % 2 ? candela::content::makeBox({0.6f, 0.6f, 0.6f})
                        : candela::content::makeSphere(0.6f, 24, 12),
                  grey, world);
    }
    scene.lookAt({0.0f, 3.0f, 4.0f}, {0.0f, 0.5f, -10.0f}, {0.0f, 1.0f, 0.0f});
    return scene;
}

// Random lights around the room plus every placement that breaks naive culling.
std::vector<LightInstance> hardLights(size_t count, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> x(-20.0f, 20.0f), y(0.05f, 4.0f), z(-40.0f, 12.0f);
    std::uniform_real_distribution<float> radius(0.5f, 4.0f), unit(0.0f, 1.0f);
    std::vector<LightInstance> lights;
    for (size_t i = 0; i < count; ++i) {
        LightInstance l =
            pointLight({x(rng), y(rng), z(rng)}, 200.0f + 800.0f * unit(rng), radius(rng));
        l.light.color = {unit(rng), unit(rng), unit(rng)};
        switch (i % 8) {
            case 1:
                l.light.sourceRadius = 0.05f + 0.3f * unit(rng);
                break;
            case 2:
                l.light.sourceLength = 0.2f + 2.0f * unit(rng);
                l.tubeAxis =
                    glm::normalize(glm::vec3(unit(rng) - 0.5f, unit(rng) - 0.5f, unit(rng) - 0.5f));
                break;
            case 3:
                l.light.type = LightType::Spot;
                l.light.outerConeAngle = 0.2f + 0.8f * unit(rng);
                l.light.innerConeAngle = 0.5f * l.light.outerConeAngle;
                l.direction = glm::normalize(glm::vec3(unit(rng) - 0.5f, -1.0f, unit(rng) - 0.5f));
                break;
            case 4:
            case 5: {
                // One-sided area lights (issue 15) facing every way: their half-sphere bounds
                // must keep every lit pixel on the CPU and GPU paths alike. Sizes and facings
                // come from the index, so the random stream (and every other light) is as it
                // was before they were added.
                const float k = float(i % 13);
                l.light.type = i % 8 == 4 ? LightType::Rect : LightType::Disk;
                l.light.width = 0.2f + 0.12f * k;
                l.light.height = 1.7f - 0.11f * k;
                l.light.sourceRadius = 0.1f + 0.05f * k;
                const float angle = 0.7f * float(i);
                l.direction = glm::normalize(
                    glm::vec3(std::cos(angle), std::sin(1.3f * angle) - 0.3f, std::sin(angle)));
                l.tubeAxis = glm::normalize(glm::cross(l.direction, glm::vec3(0.3f, 0.4f, 0.87f)));
                break;
            }
            default:
                break;
        }
        lights.push_back(l);
    }
    // Behind the camera (camera at z = 4 looking to -z), reaching into the view.
    lights.push_back(pointLight({0.5f, 2.0f, 7.0f}, 3000.0f, 8.0f));
    // Straddling the near plane.
    lights.push_back(pointLight({0.0f, 3.0f, 3.97f}, 500.0f, 2.0f));
    // A huge radius covering everything.
    lights.push_back(pointLight({4.0f, 6.0f, -10.0f}, 20000.0f, 1000.0f));
    // A spot seen edge-on: its axis across the view, its cone grazing the floor.
    LightInstance edgeOn = pointLight({-3.0f, 1.0f, -6.0f}, 5000.0f, 15.0f);
    edgeOn.light.type = LightType::Spot;
    edgeOn.light.outerConeAngle = 0.3f;
    edgeOn.light.innerConeAngle = 0.2f;
    edgeOn.direction = glm::normalize(glm::vec3(1.0f, -0.08f, 0.0f));
    lights.push_back(edgeOn);
    // A tube longer than the view.
    LightInstance tube = pointLight({0.0f, 1.5f, -12.0f}, 8000.0f, 3.0f);
    tube.light.sourceLength = 200.0f;
    tube.light.sourceRadius = 0.05f;
    tube.tubeAxis = {1.0f, 0.0f, 0.0f};
    lights.push_back(tube);
    // And a sun, which every pixel evaluates in both modes.
    LightInstance sun;
    sun.light.type = LightType::Directional;
    sun.light.lux = 5.0f;
    sun.direction = glm::normalize(glm::vec3(-0.3f, -1.0f, -0.2f));
    lights.push_back(sun);
    return lights;
}

double maxRelativeDifference(const CapturedFrame& a, const CapturedFrame& b) {
    double worst = 0.0;
    for (size_t i = 0; i < a.hdrRgb.size(); ++i) {
        double x = a.hdrRgb[i], y = b.hdrRgb[i];
        double scale = std::max(std::abs(x), std::abs(y));
        if (scale > 0.0) worst = std::max(worst, std::abs(x - y) / scale);
    }
    return worst;
}

// The light table's slot order (runtime/src/light_table.cpp), with three casters: each class
// runs in its own loop of the lighting shader and the catch-all loop is compiled out
// (render/src/passes/lighting/light_loops.h).
void arrangeByClass(std::vector<LightInstance>& lights) {
    int casters = 0;
    for (LightInstance& l : lights) {
        if (casters < 3 && l.light.type != LightType::Rect && l.light.type != LightType::Disk &&
            l.light.type != LightType::Directional && l.light.type != LightType::Spot) {
            l.light.castShadows = true;
            ++casters;
        }
    }
    const auto group = [](const LightInstance& l) {
        const bool area = l.light.type == LightType::Rect || l.light.type == LightType::Disk;
        if (l.light.castShadows) return area ? 4 : 3;
        if (area) return 2;
        return candela::content::isPlainPunctualLight(l.light) ? 0 : 1;
    };
    std::stable_sort(
        lights.begin(), lights.end(),
        [&](const LightInstance& a, const LightInstance& b) { return group(a) < group(b); });
}

void expectClusteredMatchesBruteForce(size_t lightCount, uint32_t size, bool byClass = false) {
    GpuContext context(requiredValidation());
    TestScene scene = roomScene(size);
    scene.lights = hardLights(lightCount, uint32_t(lightCount));
    if (byClass) arrangeByClass(scene.lights);
    RendererOptions clustered;
    clustered.countLightPairs = true;
    RendererOptions bruteForce = clustered;
    bruteForce.lightCulling = LightCulling::BruteForce;
    RendererStats clusteredStats, bruteStats;
    CapturedFrame a = scene.render(context, clustered, &clusteredStats);
    CapturedFrame b = scene.render(context, bruteForce, &bruteStats);
    double difference = maxRelativeDifference(a, b);
    std::printf("%zu lights: max relative difference %.3g, evaluations %llu vs %llu, lit %llu\n",
                scene.lights.size(), difference,
                (unsigned long long)clusteredStats.lightEvaluations,
                (unsigned long long)bruteStats.lightEvaluations,
                (unsigned long long)clusteredStats.litPairs);
    EXPECT_LE(difference, 1e-4);
    EXPECT_EQ(a.nonFiniteHdrValues(), 0u);
    // Culling may only skip pairs that add nothing.
    EXPECT_EQ(clusteredStats.litPairs, bruteStats.litPairs);
    EXPECT_LT(clusteredStats.lightEvaluations, bruteStats.lightEvaluations);

    // The compute-shader assignment: the same image as brute force and as the CPU lists.
    RendererOptions device = clustered;
    device.lightAssignment = LightAssignmentDevice::Gpu;
    RendererStats deviceStats;
    CapturedFrame c = scene.render(context, device, &deviceStats);
    double deviceToBrute = maxRelativeDifference(c, b);
    double deviceToCpu = maxRelativeDifference(c, a);
    std::printf(
        "  device lists: vs brute force %.3g, vs CPU lists %.3g, evaluations %llu, "
        "pairs %llu (CPU %llu)\n",
        deviceToBrute, deviceToCpu, (unsigned long long)deviceStats.lightEvaluations,
        (unsigned long long)deviceStats.lightClusterPairs,
        (unsigned long long)clusteredStats.lightClusterPairs);
    EXPECT_LE(deviceToBrute, 1e-4);
    EXPECT_LE(deviceToCpu, 1e-4);
    EXPECT_EQ(c.nonFiniteHdrValues(), 0u);
    EXPECT_EQ(deviceStats.litPairs, bruteStats.litPairs);
    EXPECT_LT(deviceStats.lightEvaluations, bruteStats.lightEvaluations);
    EXPECT_EQ(deviceStats.lightListOverflows, 0u);
    EXPECT_GT(deviceStats.lightClusterPairs, 0u);
    // The same lists with the same quarter masks: as many entries, as many evaluated pairs.
    EXPECT_EQ(deviceStats.lightClusterPairs, clusteredStats.lightClusterPairs);
    EXPECT_EQ(deviceStats.lightEvaluations, clusteredStats.lightEvaluations);
    EXPECT_EQ(context.validationMessages(), 0u);
}

}  // namespace

TEST(ClusteredLighting, MatchesBruteForceWith16Lights) {
    expectClusteredMatchesBruteForce(16, 128);
}

// Issue 41: lights in class order, the lighting shader's loops by class with no catch-all.
TEST(ClusteredLighting, MatchesBruteForceWithLightsByClass) {
    expectClusteredMatchesBruteForce(64, 96, true);
}

TEST(ClusteredLighting, MatchesBruteForceWith1024Lights) {
    expectClusteredMatchesBruteForce(1024, 128);
}

// 8,192, not more: lavapipe's loop limiter stops an invocation after 65,535 loop iterations in
// all (every loop of the shader counts), so the brute-force reference, which walks every light
// per pixel, is cut short once the lights' own loops (LTC polygon clipping and edges) add enough
// iterations: at 16,384 lights it made 74.2 million light-pixel evaluations where 8,192 lights
// made 46.4 million (not twice as many), and the comparison failed on the reference, not on the
// clusters (the clustered lit pairs outnumbered brute force's, which culling cannot do).
TEST(ClusteredLighting, MatchesBruteForceWith8192Lights) {
    expectClusteredMatchesBruteForce(8192, 96);
}

// A device list buffer far too small for the frame: the clusters that do not fit evaluate every
// light (the image still matches brute force), the overflow is counted, and the next frame's
// buffer is large enough.
TEST(ClusteredLighting, DeviceListOverflowDropsNoLightAndGrows) {
    GpuContext context(requiredValidation());
    TestScene scene = roomScene(96);
    scene.lights = hardLights(256, 7);
    RendererOptions bruteForce;
    bruteForce.lightCulling = LightCulling::BruteForce;
    CapturedFrame reference = scene.render(context, bruteForce);
    RendererOptions device;
    device.lightAssignment = LightAssignmentDevice::Gpu;
    device.initialGpuLightListEntries = 64;
    RendererStats first, second;
    CapturedFrame overflowed = scene.render(context, device, &first);
    EXPECT_EQ(first.lightListGrew, 1u);
    EXPECT_GT(first.lightListOverflows, 0u);  // clusters that took every light
    EXPECT_GT(first.lightClusterPairs, 64u);
    EXPECT_LE(maxRelativeDifference(overflowed, reference), 1e-4);
    CapturedFrame grown = scene.render(context, device, &second, 2);
    EXPECT_EQ(second.lightListGrew, 1u);  // only the first of the two frames grew
    EXPECT_EQ(second.lightListOverflows, first.lightListOverflows);  // and overflowed
    EXPECT_EQ(second.lightClusterPairs, first.lightClusterPairs);
    EXPECT_LE(maxRelativeDifference(grown, reference), 1e-4);
    EXPECT_EQ(context.validationMessages(), 0u);
}

// Lists are rewritten in place frame to frame (only the clusters that change): a frame after
// one with a different view, and so different occupied clusters, must still match brute force.
TEST(ClusteredLighting, ListsFollowTheCameraAcrossFrames) {
    GpuContext context(requiredValidation());
    TestScene scene = roomScene(96);
    scene.lights = hardLights(256, 11);
    RendererOptions bruteForce;
    bruteForce.lightCulling = LightCulling::BruteForce;
    CapturedFrame reference = scene.render(context, bruteForce);
    for (LightAssignmentDevice device : {LightAssignmentDevice::Cpu, LightAssignmentDevice::Gpu}) {
        SceneResources resources(context);
        FrameInputs second = scene.prepare(resources);
        TestScene elsewhere = scene;
        elsewhere.lookAt({6.0f, 8.0f, -25.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f});
        FrameInputs first = second;
        first.scene.camera = elsewhere.camera;
        RendererOptions options;
        options.lightAssignment = device;
        Renderer renderer(context, scene.width, scene.height, options);
        FrameSubmitter submitter(context);
        FrameReadback readback(context, scene.width, scene.height);
        for (const FrameInputs* inputs : {&first, &second, &first, &second}) {
            VkCommandBuffer cmd = renderer.recordFrame(submitter, *inputs, &resources);
            if (inputs == &second) readback.recordCopy(cmd, renderer);
            submitter.submit();
            submitter.waitIdle();
        }
        RendererStats stats = renderer.collectStats();
        double difference = maxRelativeDifference(readback.read(), reference);
        std::printf("%s assignment, fourth frame: max relative difference %.3g\n",
                    device == LightAssignmentDevice::Gpu ? "GPU" : "CPU", difference);
        EXPECT_LE(difference, 1e-4);
        // Nothing overflows; the device guess fits this scene from the first frame, and the
        // CPU path counts its first allocation as growth.
        EXPECT_EQ(stats.lightListOverflows, 0u);
        EXPECT_EQ(stats.lightListGrew, device == LightAssignmentDevice::Gpu ? 0u : 1u);
    }
    EXPECT_EQ(context.validationMessages(), 0u);
}

namespace {

// A large floor seen at a grazing angle, with `count` point lights scattered just above it:
// every pixel sees a bounded number of lights. Returns evaluated / lit pairs.
double floorCullingEfficiency(size_t count, const RendererOptions& options, uint32_t width,
                              uint32_t height) {
    GpuContext context(requiredValidation());
    TestScene scene;
    scene.width = width;
    scene.height = height;
    scene.add(candela::content::makePlane(100.0f, 8), lambertWhite());
    scene.lookAt({0.0f, 6.0f, 20.0f}, {0.0f, 0.0f, -20.0f}, {0.0f, 1.0f, 0.0f});
    // Spread over the visible floor area so light density per pixel stays bounded.
    const float extent = 4.0f * std::sqrt(float(count));
    std::mt19937 rng{uint32_t(count)};
    std::uniform_real_distribution<float> x(-extent, extent), z(-2.0f * extent, 18.0f);
    std::uniform_real_distribution<float> y(0.1f, 1.0f), radius(1.0f, 3.0f);
    for (size_t i = 0; i < count; ++i) {
        scene.lights.push_back(pointLight({x(rng), y(rng), z(rng)}, 500.0f, radius(rng)));
    }
    RendererOptions counting = options;
    counting.countLightPairs = true;
    RendererStats stats;
    scene.render(context, counting, &stats);
    EXPECT_GT(stats.litPairs, 0u);
    EXPECT_EQ(context.validationMessages(), 0u);
    return double(stats.lightEvaluations) / double(std::max<uint64_t>(stats.litPairs, 1));
}

}  // namespace

TEST(ClusteredLighting, CullingEfficiencyOnAFloor) {
    for (size_t count : {size_t(1024), size_t(16384)}) {
        RendererOptions options;  // the defaults users get
        double efficiency = floorCullingEfficiency(count, options, 320, 180);
        std::printf("%zu lights on a floor: evaluated / lit = %.3f\n", count, efficiency);
        EXPECT_LE(efficiency, 2.0);
    }
}
// Issue 22's mixed-size floor (the benchmark's `--scene mixed`) at a small size: the quarter
// masks keep evaluated / lit under 1.5, the CPU and compute
// assignments give the same entries and masks (same pairs, same evaluations, same image), and
// the image is brute force's.
TEST(ClusteredLighting, QuarterMasksOnTheMixedSizeFloor) {
    GpuContext context(requiredValidation());
    TestScene scene;
    scene.width = 320;
    scene.height = 180;
    scene.add(candela::content::makePlane(candela::render::bench::kMixedSizeFloorHalfExtent, 8),
              lambertWhite());
    scene.lookAt({0.0f, 6.0f, 20.0f}, {0.0f, 0.0f, -20.0f}, {0.0f, 1.0f, 0.0f});
    scene.lights = candela::render::bench::mixedSizeLights(1024);
    RendererOptions cpu;
    cpu.countLightPairs = true;
    RendererOptions gpu = cpu;
    gpu.lightAssignment = LightAssignmentDevice::Gpu;
    RendererOptions bruteForce = cpu;
    bruteForce.lightCulling = LightCulling::BruteForce;
    RendererStats cpuStats, gpuStats, bruteStats;
    CapturedFrame a = scene.render(context, cpu, &cpuStats);
    CapturedFrame b = scene.render(context, gpu, &gpuStats);
    CapturedFrame reference = scene.render(context, bruteForce, &bruteStats);
    const double efficiency =
        double(cpuStats.lightEvaluations) / double(std::max<uint64_t>(cpuStats.litPairs, 1));
    std::printf("mixed-size floor, 320x180: evaluated / lit = %.3f, pairs %llu (GPU %llu)\n",
                efficiency, (unsigned long long)cpuStats.lightClusterPairs,
                (unsigned long long)gpuStats.lightClusterPairs);
    EXPECT_GT(cpuStats.litPairs, 0u);
    EXPECT_EQ(cpuStats.litPairs, bruteStats.litPairs);
    EXPECT_LE(efficiency, 1.5);
    EXPECT_EQ(gpuStats.lightClusterPairs, cpuStats.lightClusterPairs);
    EXPECT_EQ(gpuStats.lightEvaluations, cpuStats.lightEvaluations);
    EXPECT_EQ(gpuStats.litPairs, cpuStats.litPairs);
    EXPECT_EQ(b.hdrRgb, a.hdrRgb);
    EXPECT_LE(maxRelativeDifference(a, reference), 1e-4);
    EXPECT_EQ(context.validationMessages(), 0u);
}

// One light reaching every cluster of a grid of spheres seen head-on at 256 x 256 (nothing
// behind them, so the slices span the spheres' depth and most tiles hold many): both
// assignment paths list it in every occupied cluster. (lavapipe ends a shader's loops after
// 65,535 iterations in all; a compute walk that spent a few more per cluster silently dropped
// clusters here.)
TEST(ClusteredLighting, LightOverEveryClusterListedEverywhereOnBothPaths) {
    GpuContext context(requiredValidation());
    TestScene scene;
    scene.width = 256;
    scene.height = 256;
    for (int i = 0; i < 49; ++i) {
        const glm::vec3 at(float(i % 7) - 3.0f, float(i / 7) - 3.0f, 0.0f);
        scene.add(candela::content::makeSphere(0.45f, 24, 12), lambertWhite(),
                  glm::translate(glm::mat4(1.0f), at));
    }
    scene.lookAt({0.0f, 0.0f, 8.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f});
    scene.lights.push_back(pointLight({-2.0f, 2.5f, 3.0f}, 6000.0f, 25.0f));
    for (LightAssignmentDevice device : {LightAssignmentDevice::Cpu, LightAssignmentDevice::Gpu}) {
        RendererOptions options;
        options.lightAssignment = device;
        RendererStats stats;
        scene.render(context, options, &stats);
        std::printf("%s: %llu pairs, %u occupied clusters\n",
                    device == LightAssignmentDevice::Gpu ? "GPU" : "CPU",
                    (unsigned long long)stats.lightClusterPairs, stats.clustersOccupied);
        EXPECT_GT(stats.clustersOccupied, 4096u);
        EXPECT_EQ(stats.lightClusterPairs, stats.clustersOccupied);
    }
    EXPECT_EQ(context.validationMessages(), 0u);
}

// The measurement behind the default tile size and slice count (render/README.md). Run with
// --gtest_filter=*TileAndSliceSweep* --gtest_also_run_disabled_tests.
TEST(ClusteredLighting, DISABLED_TileAndSliceSweep) {
    for (uint32_t width : {320u, 640u}) {
        for (size_t count : {size_t(1024), size_t(16384)}) {
            for (uint32_t tile : {8u, 16u, 32u}) {
                for (uint32_t slices : {32u, 64u}) {
                    RendererOptions options;
                    options.tileSize = tile;
                    options.slices = slices;
                    double e = floorCullingEfficiency(count, options, width, width * 9 / 16);
                    std::printf("w %u count %zu tile %u slices %u: %.3f\n", width, count, tile,
                                slices, e);
                }
            }
        }
    }
}
