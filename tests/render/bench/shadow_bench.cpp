// candela-bench-shadows: shadow cost for 1, 16, 64, 256 and 1,024 shadowed local lights plus a
// sun, over a floor with a grid of boxes casting. Per light count: the shadow pass's GPU ms
// with every map rendered (cache off) and with the maps cached (the second frame, cache on),
// the share of atlas texels in use, the lighting pass's ms with and without shadows, and the
// ratio of the shadowed frame's (shadows + lighting) to the same frame with shadows off.
// On lavapipe an uncached frame's "lighting ms" can include part of the shadow pass's
// rasterization (with 256 lights it measured 632 ms against 397 ms cached); the cached
// frame's lighting ms (no map rendered) is the cost of sampling the maps alone, and its ratio
// to the unshadowed lighting is the last column.
// Prints a markdown table of medians; it measures, it never fails on a number.
//
//   build/bin/candela-bench-shadows [--size WxH] [--max-lights N] [--repeat N]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "../test_scene.h"
#include "median.h"

using namespace candela::render;
using namespace candela::render::test;
using candela::median;

namespace {

// A 40 m floor, a 10 x 10 grid of boxes, a sun and `count` point, sphere, tube and spot lights
// over it on a jittered grid (every fourth a spot), all casting when `shadows`.
TestScene benchScene(size_t count, uint32_t width, uint32_t height, bool shadows) {
    TestScene scene;
    scene.width = width;
    scene.height = height;
    scene.add(candela::content::makePlane(20.0f, 8), lambertWhite());
    for (int z = 0; z < 10; ++z) {
        for (int x = 0; x < 10; ++x) {
            scene.add(candela::content::makeBox({0.3f, 0.5f, 0.3f}), lambertWhite(),
                      glm::translate(glm::mat4(1.0f), glm::vec3(-18.0f + 4.0f * float(x), 0.5f,
                                                                -18.0f + 4.0f * float(z))));
        }
    }
    scene.lookAt({0.0f, 12.0f, 22.0f}, {0.0f, 0.0f, -4.0f}, {0.0f, 1.0f, 0.0f});
    LightInstance sun;
    sun.light.type = candela::content::LightType::Directional;
    sun.light.lux = 2.0f;
    sun.light.castShadows = shadows;
    sun.direction = glm::normalize(glm::vec3(0.4f, -1.0f, 0.3f));
    scene.lights.push_back(sun);
    const size_t side = size_t(std::ceil(std::sqrt(double(count))));
    for (size_t i = 0; i < count; ++i) {
        const float fx = (float(i % side) + 0.5f) / float(side);
        const float fz = (float(i / side) + 0.5f) / float(side);
        LightInstance l = pointLight(
            {-19.0f + 38.0f * fx, 1.5f + float(i % 3) * 0.5f, -19.0f + 38.0f * fz}, 400.0f, 3.0f);
        l.light.castShadows = shadows;
        if (i % 4 == 1) l.light.sourceRadius = 0.1f;
        if (i % 4 == 2) l.light.sourceLength = 0.6f;
        if (i % 4 == 3) {
            l.light.type = candela::content::LightType::Spot;
            l.light.outerConeAngle = 0.8f;
            l.light.innerConeAngle = 0.5f;
            l.direction = glm::vec3(0.0f, -1.0f, 0.0f);
        }
        scene.lights.push_back(l);
    }
    return scene;
}

}  // namespace

int main(int argc, char** argv) {
    uint32_t width = 320, height = 180;
    size_t maxLights = 1024;
    int repeat = 3;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--size" && i + 1 < argc) {
            if (std::sscanf(argv[++i], "%ux%u", &width, &height) != 2) {
                std::fprintf(stderr, "--size expects WxH\n");
                return 2;
            }
        } else if (arg == "--max-lights" && i + 1 < argc) {
            maxLights = size_t(std::strtoul(argv[++i], nullptr, 10));
        } else if (arg == "--repeat" && i + 1 < argc) {
            repeat = std::max(1, std::atoi(argv[++i]));
        } else {
            std::fprintf(stderr,
                         "usage: candela-bench-shadows [--size WxH] [--max-lights N] "
                         "[--repeat N]\n");
            return 2;
        }
    }
    GpuContext context(GpuContextOptions{});
    std::printf("candela-bench-shadows: %ux%u, %s, medians of %d\n\n", width, height,
                context.deviceName().c_str(), repeat);
    std::printf(
        "| shadowed local lights + sun | shadow ms (all rendered) | shadow ms (cached) | maps "
        "cached | atlas used | lighting ms (shadows) | lighting ms (off) | (shadow + lighting) / "
        "lighting off | lighting ms (cached maps) | cached lighting / lighting off "
        "|\n|---|---|---|---|---|---|---|---|---|---|\n");
    for (size_t count : {size_t(1), size_t(16), size_t(64), size_t(256), size_t(1024)}) {
        if (count > maxLights) break;
        std::vector<double> shadowMs, cachedMs, litMs, offMs, ratios, cachedLitMs, cachedRatios;
        RendererStats on{}, cached{}, off{};
        for (int r = 0; r < repeat; ++r) {
            RendererOptions uncachedOptions;
            uncachedOptions.shadowCache = false;
            TestScene shadowed = benchScene(count, width, height, true);
            shadowed.render(context, uncachedOptions, &on, 2);
            TestScene cachedScene = benchScene(count, width, height, true);
            cachedScene.render(context, {}, &cached, 2);
            TestScene plain = benchScene(count, width, height, false);
            plain.render(context, {}, &off, 2);
            shadowMs.push_back(on.shadowMs);
            cachedMs.push_back(cached.shadowMs);
            litMs.push_back(on.lightingMs);
            offMs.push_back(off.lightingMs);
            ratios.push_back((on.shadowMs + on.lightingMs) / std::max(off.lightingMs, 1e-6));
            cachedLitMs.push_back(cached.lightingMs);
            cachedRatios.push_back(cached.lightingMs / std::max(off.lightingMs, 1e-6));
        }
        std::printf(
            "| %zu | %.2f | %.2f | %u of %u | %.1f%% | %.2f | %.2f | %.2f | %.2f | %.2f |\n", count,
            median(shadowMs), median(cachedMs), cached.shadowMapsCached, cached.shadowedLights,
            100.0 * on.shadowAtlasUsed, median(litMs), median(offMs), median(ratios),
            median(cachedLitMs), median(cachedRatios));
        std::fflush(stdout);
    }
    return 0;
}
