// Shadow planning without a device (issue 14): the practical cascade splits, cascades that keep
// their texel grid when the camera moves or turns, and the atlas packing that shrinks the least
// important maps instead of dropping any, and the per-frame render budget under which changed
// lights keep last frame's maps instead of re-rendering.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "passes/shadows/cascades.h"
#include "passes/shadows/shadow_atlas.h"
#include "passes/shadows/shadow_render_budget.h"

using namespace candela::render;

namespace {

CameraView cameraAt(const glm::vec3& eye, const glm::vec3& target) {
    CameraView c;
    c.view = glm::lookAt(eye, target, glm::vec3(0, 1, 0));
    c.projection = reverseZPerspective(glm::radians(60.0f), 16.0f / 9.0f, 0.05f);
    c.nearPlane = 0.05f;
    c.position = eye;
    return c;
}

// Where a world point lands in a cascade's texel grid (texels from the map's corner).
glm::vec2 texelOf(const CascadeView& c, const glm::vec3& p, uint32_t resolution) {
    const glm::vec4 clip = c.worldToClip * glm::vec4(p, 1.0f);
    return (glm::vec2(clip) * 0.5f + 0.5f) * float(resolution);
}

const glm::vec3 kSun = glm::normalize(glm::vec3(-0.4f, -0.8f, -0.45f));

}  // namespace

TEST(ShadowCascades, PracticalSplitsCoverTheRangeInIncreasingSlices) {
    const std::vector<float> s = practicalSplits(0.05f, 50.0f, 4, kPracticalSplitLambda);
    ASSERT_EQ(s.size(), 5u);
    EXPECT_FLOAT_EQ(s.front(), 0.05f);
    EXPECT_FLOAT_EQ(s.back(), 50.0f);
    for (size_t i = 1; i < s.size(); ++i)
        EXPECT_GT(s[i], s[i - 1]);
    // Mostly logarithmic: the first slice is far shorter than the uniform 12.5 m.
    EXPECT_LT(s[1], 5.0f);
}

TEST(ShadowCascades, AMovedOrTurnedCameraKeepsEveryTexelWhereItWas) {
    constexpr uint32_t kResolution = 1024;
    const CameraView a = cameraAt({1.0f, 3.0f, 6.0f}, {0.0f, 0.0f, -4.0f});
    const std::vector<float> s = practicalSplits(0.05f, 50.0f, 4, kPracticalSplitLambda);
    for (uint32_t i = 0; i < 4; ++i) {
        const CascadeView ca = fitCascade(a, s[i], s[i + 1], kSun, kResolution, -20.0f);
        // Moved by a tenth of a texel along x, and turned by a tenth of a degree.
        CameraView moved = a;
        const glm::vec3 step(0.1f * ca.texelWorld, 0.0f, 0.0f);
        moved.view = glm::translate(a.view, -step);
        moved.position = a.position + step;
        CameraView turned = a;
        turned.view = glm::rotate(glm::mat4(1.0f), glm::radians(0.1f), glm::vec3(0, 1, 0)) * a.view;
        for (const CameraView& b : {moved, turned}) {
            const CascadeView cb = fitCascade(b, s[i], s[i + 1], kSun, kResolution, -20.0f);
            EXPECT_EQ(cb.texelWorld, ca.texelWorld) << "cascade " << i;
            EXPECT_EQ(cb.sphere.w, ca.sphere.w) << "cascade " << i;
            EXPECT_EQ(cb.nearDepth, ca.nearDepth) << "cascade " << i;
            // Any world point is the same fraction of a texel into its texel in both maps.
            for (const glm::vec3 p :
                 {glm::vec3(0.3f, 0.0f, -1.7f), glm::vec3(-2.1f, 0.5f, -3.3f)}) {
                const glm::vec2 shift = texelOf(cb, p, kResolution) - texelOf(ca, p, kResolution);
                EXPECT_NEAR(shift.x, std::round(shift.x), 2e-3f) << "cascade " << i;
                EXPECT_NEAR(shift.y, std::round(shift.y), 2e-3f) << "cascade " << i;
            }
        }
    }
}

TEST(ShadowAtlas, TilesLieInsideTheAtlasAndNeverOverlap) {
    std::vector<ShadowTileRequest> requests = {
        {4, 1024, 0.0f, false}, {6, 256, 5.0f}, {1, 512, 3.0f}, {6, 64, 1.0f}, {1, 16, 0.5f}};
    const ShadowAtlasPlan plan = planShadowAtlas(requests, 4096);
    ASSERT_TRUE(plan.fits);
    std::vector<ShadowTile> all;
    for (size_t r = 0; r < requests.size(); ++r) {
        ASSERT_EQ(plan.tiles[r].size(), requests[r].tiles);
        EXPECT_EQ(plan.sizes[r], requests[r].size);  // fits: nothing shrinks
        for (const ShadowTile& t : plan.tiles[r]) {
            EXPECT_LE(t.x + t.size, 4096u);
            EXPECT_LE(t.y + t.size, 4096u);
            EXPECT_EQ(t.x % t.size, 0u);
            all.push_back(t);
        }
    }
    for (size_t i = 0; i < all.size(); ++i) {
        for (size_t j = i + 1; j < all.size(); ++j) {
            const bool apart =
                all[i].x + all[i].size <= all[j].x || all[j].x + all[j].size <= all[i].x ||
                all[i].y + all[i].size <= all[j].y || all[j].y + all[j].size <= all[i].y;
            EXPECT_TRUE(apart) << i << " and " << j;
        }
    }
}

TEST(ShadowAtlas, OverBudgetTheLeastImportantShrinkAndNoneIsDropped) {
    // A sun's 4 x 1024 cascades and 1,024 cube-mapped lights wanting 256 per face: 400M
    // texels wanted from a 16.7M atlas.
    std::vector<ShadowTileRequest> requests = {{4, 1024, 0.0f, false}};
    for (int i = 0; i < 1024; ++i)
        requests.push_back({6, 256, float(i)});
    const ShadowAtlasPlan plan = planShadowAtlas(requests, 4096);
    ASSERT_TRUE(plan.fits);
    EXPECT_EQ(plan.sizes[0], 1024u);  // cascades keep their size
    for (size_t r = 0; r < requests.size(); ++r) {
        EXPECT_EQ(plan.tiles[r].size(), requests[r].tiles) << "request " << r;
    }
    // Sizes never decrease with importance, and the most important kept more than the least.
    for (size_t r = 2; r < requests.size(); ++r)
        EXPECT_GE(plan.sizes[r], plan.sizes[r - 1]);
    EXPECT_GT(plan.sizes.back(), plan.sizes[1]);
    EXPECT_LE(plan.usedTexels, uint64_t(4096) * 4096);
}

namespace {

size_t countOf(const std::vector<ShadowRenderChoice>& choices, ShadowRenderChoice which) {
    return size_t(std::count(choices.begin(), choices.end(), which));
}

}  // namespace

TEST(ShadowRenderBudget, OverBudgetChangedLightsKeepLastFramesMapsAndNoneIsDropped) {
    // Ten changed cube lights of 6 x 64^2 texels whose maps are still in the atlas, two that
    // did not change, and one changed light whose tiles moved (nothing valid to keep).
    constexpr uint64_t kLight = 6 * 64 * 64;
    std::vector<ShadowRenderCandidate> lights;
    for (int i = 0; i < 10; ++i)
        lights.push_back({kLight, true, true, float(i), 0});
    lights.push_back({kLight, false, true, 100.0f, 0});
    lights.push_back({kLight, false, false, 100.0f, 0});
    lights.push_back({kLight, true, false, -1.0f, 0});
    // Room for four: the moved light must render, then the three most important.
    const std::vector<ShadowRenderChoice> c = planShadowRenders(lights, 4 * kLight);
    ASSERT_EQ(c.size(), lights.size());
    EXPECT_EQ(c[12], ShadowRenderChoice::Render);
    EXPECT_EQ(c[10], ShadowRenderChoice::Cached);
    EXPECT_EQ(c[11], ShadowRenderChoice::Cached);
    for (int i = 0; i < 10; ++i) {
        EXPECT_EQ(c[i], i >= 7 ? ShadowRenderChoice::Render : ShadowRenderChoice::Keep)
            << "light " << i;
    }
    EXPECT_EQ(countOf(c, ShadowRenderChoice::Render), 4u);
    // No budget: every changed light renders.
    const std::vector<ShadowRenderChoice> all = planShadowRenders(lights, 0);
    EXPECT_EQ(countOf(all, ShadowRenderChoice::Render), 11u);
    EXPECT_EQ(countOf(all, ShadowRenderChoice::Keep), 0u);
    // A budget smaller than any map still renders one light a frame.
    const std::vector<ShadowRenderChoice> tiny = planShadowRenders(lights, 1);
    EXPECT_EQ(countOf(tiny, ShadowRenderChoice::Render), 2u);  // the moved one and one more
    EXPECT_EQ(tiny[9], ShadowRenderChoice::Render);
}

TEST(ShadowRenderBudget, EveryChangedLightRendersWithinAFewFrames) {
    // 20 lights that change every frame, of unequal importance, with room for 3 a frame: each
    // must be brought up to date within ceil(20 / 3) = 7 frames, however unimportant.
    constexpr size_t kLights = 20;
    constexpr uint64_t kLight = 1000;
    std::vector<ShadowRenderCandidate> lights(kLights);
    for (size_t i = 0; i < kLights; ++i)
        lights[i] = {kLight, true, true, float(i * i), 0};
    std::vector<uint32_t> longestWait(kLights, 0);
    for (int frame = 0; frame < 50; ++frame) {
        const std::vector<ShadowRenderChoice> c = planShadowRenders(lights, 3 * kLight);
        EXPECT_EQ(countOf(c, ShadowRenderChoice::Render), 3u) << "frame " << frame;
        for (size_t i = 0; i < kLights; ++i) {
            // What the shadow pass does: a kept map waits one frame more, a rendered one none.
            lights[i].framesWaiting =
                c[i] == ShadowRenderChoice::Keep ? lights[i].framesWaiting + 1 : 0;
            longestWait[i] = std::max(longestWait[i], lights[i].framesWaiting);
        }
    }
    for (size_t i = 0; i < kLights; ++i)
        EXPECT_LE(longestWait[i], 6u) << "light " << i << " kept a stale map too long";
}
