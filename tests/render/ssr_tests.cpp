// Issue 18: screen-space reflections by Hi-Z tracing. A mirror floor under an emissive box
// against a CPU ray trace (edges ±1 pixel), at an odd resolution too, the step counts of
// Hi-Z against the linear reference march, and no pass where nothing is glossy.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "ssr_scene.h"

namespace candela::render::test {
namespace {

RendererOptions ssrOptions(SsrMode mode) {
    RendererOptions options;
    options.ssr = mode;
    return options;
}

bool hasPass(const RendererStats& stats, const std::string& name) {
    return std::any_of(stats.passMs.begin(), stats.passMs.end(),
                       [&](const RendererStats::PassTime& p) { return p.first == name; });
}

void expectMirrorMatchesRayTrace(uint32_t width, uint32_t height, SsrMode mode,
                                 RendererStats* statsOut = nullptr) {
    GpuContext& context = sharedContext();
    MirrorUnderBox mirror(width, height);
    RendererStats stats;
    const CapturedFrame frame = mirror.scene().render(context, ssrOptions(mode), &stats);
    const MirrorComparison c = compareMirror(mirror, frame);
    EXPECT_TRUE(c.finite);
    EXPECT_GT(c.boxRadiance, 1.0);
    // The reflection covers a fair part of the floor, at the box's radiance, and nothing else
    // on the floor is lit (no sky, no light: the floor shows only what it mirrors).
    EXPECT_GT(c.boxPixels, width * height / 100) << width << "x" << height;
    EXPECT_EQ(c.boxPixelsWrong, 0u) << "worst relative error " << c.worstBoxError;
    EXPECT_GT(c.blackPixels, width * height / 10);
    EXPECT_EQ(c.blackPixelsWrong, 0u);
    EXPECT_TRUE(hasPass(stats, "ssr_trace"));
    EXPECT_GT(stats.ssrHitRate, 0.0);
    EXPECT_LT(stats.ssrHitRate, 1.0);
    if (statsOut) *statsOut = stats;
}

TEST(Ssr, MirrorFloorShowsTheBoxWhereARayTracePutsIt) {
    RendererStats stats;
    expectMirrorMatchesRayTrace(128, 128, SsrMode::Hiz, &stats);
    EXPECT_LT(stats.ssrStepsMax, RendererOptions{}.ssrSettings.maxIterations);  // none stuck

    // Without SSR the same floor shows nothing: the reflection above came from the trace.
    GpuContext& context = sharedContext();
    MirrorUnderBox mirror(128, 128);
    RendererStats offStats;
    const MirrorComparison off =
        compareMirror(mirror, mirror.scene().render(context, ssrOptions(SsrMode::Off), &offStats));
    EXPECT_EQ(off.boxPixelsWrong, off.boxPixels);
    EXPECT_FALSE(hasPass(offStats, "ssr_trace"));
    EXPECT_EQ(offStats.ssrMs, 0.0);
}

TEST(Ssr, OddResolutionsMirrorLikeEvenOnes) {
    // Hi-Z levels of 127x95 round up (64x48, 32x24, ..., 1x1): a coarse texel still covers
    // every finer one, so no ray slips past a surface at a level's last row or column.
    expectMirrorMatchesRayTrace(127, 95, SsrMode::Hiz);
    expectMirrorMatchesRayTrace(97, 129, SsrMode::Hiz);
}

TEST(Ssr, HizTakesAQuarterOfTheLinearMarchStepsForTheSameHits) {
    RendererStats hiz, reference;
    expectMirrorMatchesRayTrace(128, 128, SsrMode::Hiz, &hiz);
    expectMirrorMatchesRayTrace(128, 128, SsrMode::Reference, &reference);
    // The same rays hit (within 1% of them) and both match the ray trace above; Hi-Z takes at
    // most a quarter of the steps, and no ray runs out of iterations.
    std::printf(
        "hiz: steps mean %.2f max %u hit rate %.4f; reference: steps mean %.2f max %u "
        "hit rate %.4f\n",
        hiz.ssrStepsMean, hiz.ssrStepsMax, hiz.ssrHitRate, reference.ssrStepsMean,
        reference.ssrStepsMax, reference.ssrHitRate);
    EXPECT_NEAR(hiz.ssrHitRate, reference.ssrHitRate, 0.01);
    EXPECT_LE(4.0 * hiz.ssrStepsMean, reference.ssrStepsMean)
        << "hiz " << hiz.ssrStepsMean << " reference " << reference.ssrStepsMean;
    EXPECT_LT(hiz.ssrStepsMax, RendererOptions{}.ssrSettings.maxIterations);
    EXPECT_LT(reference.ssrStepsMax, RendererOptions{}.ssrSettings.referenceMaxSteps);
}

// Where a ray hits, the reflection replaces the sky's split-sum specular as the lighting pass
// left it, ambient occlusion included. A mirror floor (white metal: no diffuse) in front of
// an emissive wall standing on it, under a uniform sky: the floor by the wall's foot reflects
// the wall and is occluded by it, yet shows the wall exactly as with AO off, while GTAO darkens
// the sky's reflection further out (it is at work on this floor).
TEST(Ssr, ReplacesTheSkySpecularAsAmbientOcclusionLeftIt) {
    GpuContext& context = sharedContext();
    TestScene scene;
    scene.width = 64;
    scene.height = 64;
    content::Material mirror;
    mirror.baseColorFactor = {1.0f, 1.0f, 1.0f, 1.0f};
    mirror.metallicFactor = 1.0f;
    mirror.roughnessFactor = 0.0f;
    scene.add(content::makePlane(10.0f), mirror);
    content::Material glow;
    glow.shadingModel = content::ShadingModel::Unlit;
    glow.baseColorFactor = {0.0f, 0.0f, 0.0f, 1.0f};
    glow.emissiveFactor = {1.0f, 1.0f, 1.0f};
    const float emission = 4.0f;
    glow.emissiveStrength = emission;
    scene.add(content::makeBox({1.5f, 0.5f, 0.25f}), glow,
              glm::translate(glm::mat4(1.0f), {0.0f, 0.5f, -3.0f}));
    scene.lookAt({0.0f, 0.8f, 0.5f}, {0.0f, 0.1f, -3.0f}, {0.0f, 1.0f, 0.0f});
    scene.environment = Environment::uniform(context, 1.0f);
    RendererOptions off = ssrOptions(SsrMode::Hiz);
    RendererOptions gtao = off;
    gtao.ao = AoMode::Gtao;
    const CapturedFrame a = scene.render(context, off);
    const CapturedFrame b = scene.render(context, gtao);
    auto floorAt = [&](int x, int y) {
        std::optional<glm::vec3> p = scene.pixelOnPlane(uint32_t(x), uint32_t(y));
        return p && p->z > -2.7f;  // in front of the wall (not the wall itself)
    };
    auto green = [](const CapturedFrame& f, int x, int y) {
        return double(hdrPixel(f, uint32_t(x), uint32_t(y))[1]);
    };
    // Floor pixels that mirror the wall (and whose neighbours do: edges left out), away from
    // the screen border, where the confidence fades.
    auto mirrorsWall = [&](int x, int y) {
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                if (!floorAt(x + dx, y + dy) || green(a, x + dx, y + dy) < 0.5 * emission) {
                    return false;
                }
            }
        }
        return true;
    };
    double worstWall = 0.0, worstSky = 0.0;
    uint32_t wallPixels = 0;
    const int border = 4;
    for (int y = border; y < int(a.height) - border; ++y) {
        for (int x = border; x < int(a.width) - border; ++x) {
            if (!floorAt(x, y)) continue;
            const double d = std::abs(green(a, x, y) - green(b, x, y));
            if (mirrorsWall(x, y)) {
                worstWall = std::max(worstWall, d / emission);
                ++wallPixels;
            } else if (green(a, x, y) < 1.5) {
                worstSky = std::max(worstSky, d);  // the sky's radiance is 1
            }
        }
    }
    std::printf("wall pixels %u: worst |gtao - off| / wall %.2e; sky: worst %.4f\n", wallPixels,
                worstWall, worstSky);
    EXPECT_GT(wallPixels, 20u);
    EXPECT_LT(worstWall, 1e-3);
    EXPECT_GT(worstSky, 0.01);
    EXPECT_EQ(b.nonFiniteHdrValues(), 0u);
}

TEST(Ssr, FramesWithoutGlossySurfacesDeclareNoPass) {
    GpuContext& context = sharedContext();
    MirrorUnderBox rough(64, 64, 0.8f);  // over the cut-off
    RendererStats stats;
    const CapturedFrame frame = rough.scene().render(context, ssrOptions(SsrMode::Hiz), &stats);
    EXPECT_FALSE(hasPass(stats, "ssr_trace"));
    EXPECT_FALSE(hasPass(stats, "ssr_hiz0"));
    EXPECT_EQ(stats.ssrMs, 0.0);
    EXPECT_EQ(stats.ssrRays, 0u);
    EXPECT_GT(frame.width, 0u);
}

// Frames from one renderer (its SSR history carries over) with the box moved by `offsets`,
// each with motion vectors from the previous frame's offset; returns the last.
CapturedFrame renderMoving(MirrorUnderBox& mirror, const std::vector<float>& offsets,
                           std::vector<CapturedFrame>* all = nullptr) {
    GpuContext& context = sharedContext();
    TestScene& scene = mirror.scene();
    SceneResources resources(context);
    FrameSequence frames(context, scene.width, scene.height, ssrOptions(SsrMode::Hiz));
    CapturedFrame last;
    float previous = offsets.front();
    for (float x : offsets) {
        FrameInputs inputs = scene.prepare(resources);
        std::vector<DrawItem>& draws = scene.draws;
        const glm::mat4 boxWorld = draws[1].world;
        draws[1].world = glm::translate(glm::mat4(1.0f), {x, 0.0f, 0.0f}) * boxWorld;
        const std::vector<glm::mat4> previousWorlds = {
            draws[0].world, glm::translate(glm::mat4(1.0f), {previous, 0.0f, 0.0f}) * boxWorld};
        inputs.scene.previousWorlds = previousWorlds;
        previous = x;
        last = frames.render(inputs, resources);
        if (all) all->push_back(last);
    }
    return last;
}

// The largest difference of the floor's radiance between two frames, relative to `scale`.
double worstFloorDifference(const MirrorUnderBox& mirror, const CapturedFrame& a,
                            const CapturedFrame& b, double scale) {
    double worst = 0.0;
    for (uint32_t y = 0; y < a.height; ++y) {
        for (uint32_t x = 0; x < a.width; ++x) {
            if (mirror.truth(int(x), int(y)) == MirrorUnderBox::Truth::NotFloor) continue;
            worst = std::max(worst,
                             std::abs(double(hdrPixel(a, x, y)[1]) - hdrPixel(b, x, y)[1]) / scale);
        }
    }
    return worst;
}

TEST(Ssr, MovingObjectLeavesNoTrailAndAStillViewStaysPut) {
    MirrorUnderBox mirror(64, 64);
    // The box slides sideways by 0.4 m a frame for 4 frames: after them the floor shows what a
    // frame without history shows (no part of the old reflections left over 5%).
    const CapturedFrame moved = renderMoving(mirror, {0.0f, 0.4f, 0.8f, 1.2f, 1.6f});
    const CapturedFrame fresh = renderMoving(mirror, {1.6f});
    const double box = compareMirror(mirror, fresh).boxRadiance;
    EXPECT_LT(worstFloorDifference(mirror, moved, fresh, box), 0.05);
    // Still: every frame is the first (the filter converges at once and stays).
    std::vector<CapturedFrame> still;
    renderMoving(mirror, {0.0f, 0.0f, 0.0f}, &still);
    for (const CapturedFrame& f : still) {
        EXPECT_LT(worstFloorDifference(mirror, f, still.front(), box), 1e-4);
        EXPECT_TRUE(compareMirror(mirror, f).finite);
    }
}

}  // namespace
}  // namespace candela::render::test
