// Quarter-tile masks of the clustered light lists (issue 22): each list entry says which 8 px
// quarters of its 16 px tile the light reaches, from the box around each quarter's pixels, and
// a pixel evaluates only the entries with its quarter's bit. Runs on the CPU alone: a
// hand-built cluster, and the analytic floors of the benchmarks.
#include <gtest/gtest.h>

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>
#include <random>

#include "bench/analytic_floor.h"
#include "bench/list_efficiency.h"
#include "candela/ecs/job_system.h"
#include "clustered/light_bounds.h"
#include "clustered/quarter_box_test.h"

using namespace candela::render;
using namespace candela::render::bench;

namespace {

constexpr uint32_t kQuarterBits[4] = {1u << 28, 1u << 29, 1u << 30, 1u << 31};

LightInstance pointAt(const glm::vec3& viewPosition, float radius) {
    LightInstance l;
    l.light.type = candela::content::LightType::Point;
    l.light.lumens = 500.0f;
    l.light.attenuationRadius = radius;
    l.position = viewPosition;  // the view below is the identity
    return l;
}

// One 16 x 16 px tile, one slice: a single cluster whose four quarters hold a 1 m box of
// pixels each, 10 m in front of the camera, one per screen corner (view space, y up).
// bounds: the cluster's box, then its quarters' (light_list_entry.h).
struct OneCluster {
    ClusterGrid grid;
    uint64_t tileMask = 1;
    float bounds[CLUSTER_BOUNDS_FLOATS];
    float* quarters = bounds + CLUSTER_BOX_FLOATS;

    OneCluster() {
        const glm::mat4 projection = reverseZPerspective(glm::radians(60.0f), 1.0f, 0.05f);
        grid = ClusterGrid::make(16, 1, 16, 16, projection[0][0], projection[1][1], 0.05f, 100.0f);
        grid.setSlicing(9.0f, std::log(12.0f / 9.0f));
        // Quarter q = right + 2 * lower: screen rows grow downwards, view y upwards.
        for (uint32_t q = 0; q < 4; ++q) {
            const glm::vec3 centre(q % 2 ? 3.0f : -3.0f, q / 2 ? -3.0f : 3.0f, -10.0f);
            for (int c = 0; c < 3; ++c) {
                quarters[q * 6 + c] = centre[c] - 0.5f;
                quarters[q * 6 + 3 + c] = centre[c] + 0.5f;
            }
        }
        updateClusterBox();
    }
    // The cluster's box is its quarters' union.
    void updateClusterBox() {
        for (int c = 0; c < 3; ++c) {
            bounds[c] = kEmptyQuarterBound;
            bounds[3 + c] = -kEmptyQuarterBound;
            for (uint32_t q = 0; q < 4; ++q) {
                bounds[c] = std::min(bounds[c], quarters[q * 6 + c]);
                bounds[3 + c] = std::max(bounds[3 + c], quarters[q * 6 + 3 + c]);
            }
        }
    }
    void emptyQuarter(uint32_t q) {
        for (int c = 0; c < 3; ++c) {
            quarters[q * 6 + c] = kEmptyQuarterBound;
            quarters[q * 6 + 3 + c] = -kEmptyQuarterBound;
        }
        updateClusterBox();
    }
    // The cluster's list after assigning `lights` (entries: index | quarter bits).
    std::vector<uint32_t> list(const std::vector<LightInstance>& lights, bool withBounds = true) {
        ClusterOccupancy occupancy;
        occupancy.tileMasks = {&tileMask, 1};
        if (withBounds) occupancy.pixelBounds = bounds;
        std::vector<uint32_t> ranges(2, 0);
        LightAssignment out;
        assignLights(grid, lights, glm::mat4(1.0f), occupancy, nullptr, ranges, out);
        return {out.lightIndices.begin() + ranges[0],
                out.lightIndices.begin() + ranges[0] + ranges[1]};
    }
};

}  // namespace

TEST(LightQuarterMask, EntriesCarryTheQuartersTheLightReaches) {
    OneCluster cluster;
    const std::vector<LightInstance> lights = {
        pointAt({-3.0f, -3.0f, -8.5f}, 1.2f),  // 1.0 m above the lower-left box only
        pointAt({0.0f, 3.0f, -10.0f}, 2.6f),   // between the two upper boxes, reaching both
        pointAt({0.0f, 0.0f, -10.0f}, 1.5f),   // inside the cluster's box, reaching no quarter
        pointAt({3.0f, -3.0f, -10.0f}, 0.2f),  // inside the lower-right box
    };
    const std::vector<uint32_t> list = cluster.list(lights);
    ASSERT_EQ(list.size(), 3u);
    EXPECT_EQ(list[0], 0u | kQuarterBits[2]);
    EXPECT_EQ(list[1], 1u | kQuarterBits[0] | kQuarterBits[1]);
    EXPECT_EQ(list[2], 3u | kQuarterBits[3]);
}

TEST(LightQuarterMask, EmptyQuartersGetNoBit) {
    OneCluster cluster;
    cluster.emptyQuarter(1);
    const std::vector<LightInstance> lights = {
        pointAt({0.0f, 3.0f, -10.0f}, 2.6f),  // would reach quarters 0 and 1
        pointAt({3.0f, 3.0f, -10.0f}, 0.2f),  // only where quarter 1 has no pixel
    };
    const std::vector<uint32_t> list = cluster.list(lights);
    ASSERT_EQ(list.size(), 1u);
    EXPECT_EQ(list[0], 0u | kQuarterBits[0]);
}

// Without pixel bounds (no depth refinement) every entry covers the whole tile.
TEST(LightQuarterMask, WithoutPixelBoundsEveryQuarter) {
    OneCluster cluster;
    const std::vector<uint32_t> list = cluster.list({pointAt({-3.0f, -3.0f, -8.5f}, 1.2f)}, false);
    ASSERT_EQ(list.size(), 1u);
    EXPECT_EQ(list[0], 0u | LIGHT_ENTRY_ALL_QUARTERS);
}

// The analytic floors: every lit pixel's light carries the pixel's quarter bit (the masks drop
// nothing, list_efficiency counts a lit pair only through a set bit), and the masks bring
// evaluated / lit under 1.5 where whole-cluster lists cannot go (render/README.md).
TEST(LightQuarterMask, FloorsEvaluateAtMostOneAndAHalfPairsPerLitPair) {
    candela::ecs::JobSystem jobs(1);
    for (bool mixed : {false, true}) {
        const AnalyticFloorView floor =
            analyticFloorView(640, 360, mixed ? kMixedSizeFloorHalfExtent : 100.0f);
        const std::vector<LightInstance> lights = mixed ? mixedSizeLights(1024) : floorLights(1024);
        std::vector<uint32_t> ranges(size_t(floor.grid.clusterCount()) * 2, 0);
        LightAssignment assignment;
        assignLights(floor.grid, lights, floor.view, floor.occupancy(), &jobs, ranges, assignment);
        const ListEfficiency e = listEfficiency(floor, lights, assignment, ranges);
        std::printf("%s floor, 640x360: %.3f with quarter masks, %.3f without\n",
                    mixed ? "mixed-size" : "test", e.lists, e.listsUnmasked);
        EXPECT_GT(e.litPairs, 0u);
        EXPECT_EQ(e.maskedLitPairs, e.litPairs);
        EXPECT_LE(e.lists, 1.5);
        EXPECT_LT(e.lists, e.listsUnmasked);
    }
}

// The walk's four-wide quarter test (quarter_box_test.h) gives the masks the scalar per-box
// test gives, bit for bit: random spheres, capsules and cones against random clusters with one
// to four occupied quarters, many of them grazing (radius near the distance), each mask only
// for a light that passed the cluster box test, as in the walk.
TEST(LightQuarterMask, FourWideTestEqualsTheScalarOne) {
    std::mt19937 rng(22);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    auto in = [&](float lo, float hi) { return lo + (hi - lo) * unit(rng); };
    constexpr float kPad = 1e-4f;  // as light_assignment.cpp's kPixelBoundsMargin
    uint32_t compared = 0, partial = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        // One cluster: its quarters (some empty) and their union, in the buffer's layout.
        float bounds[CLUSTER_BOUNDS_FLOATS];
        float* quarters = bounds + CLUSTER_BOX_FLOATS;
        const glm::vec3 centre(in(-4.0f, 4.0f), in(-4.0f, 4.0f), in(-40.0f, -1.0f));
        uint32_t occupied = 0;
        while (occupied == 0)
            occupied = uint32_t(rng() & 15u);
        for (int c = 0; c < 3; ++c) {
            bounds[c] = kEmptyQuarterBound;
            bounds[3 + c] = -kEmptyQuarterBound;
        }
        for (uint32_t q = 0; q < 4; ++q) {
            for (int c = 0; c < 3; ++c) {
                const float a = centre[c] + in(-1.0f, 1.0f), b = centre[c] + in(-1.0f, 1.0f);
                const bool has = occupied >> q & 1u;
                quarters[q * 6 + c] = has ? std::min(a, b) : kEmptyQuarterBound;
                quarters[q * 6 + 3 + c] = has ? std::max(a, b) : -kEmptyQuarterBound;
                bounds[c] = std::min(bounds[c], quarters[q * 6 + c]);
                bounds[3 + c] = std::max(bounds[3 + c], quarters[q * 6 + 3 + c]);
            }
        }
        LightInstance light;
        const uint32_t kind = uint32_t(rng() % 3);
        light.light.type =
            kind == 2 ? candela::content::LightType::Spot : candela::content::LightType::Point;
        light.position = centre + glm::vec3(in(-3.0f, 3.0f), in(-3.0f, 3.0f), in(-3.0f, 3.0f));
        light.light.attenuationRadius = in(0.05f, 3.0f);
        if (kind == 1) {
            light.light.sourceLength = in(0.1f, 2.0f);
            light.tubeAxis = glm::normalize(glm::vec3(in(-1, 1), in(-1, 1), in(-1, 1)) + 1e-3f);
        }
        if (kind == 2) {
            light.light.outerConeAngle = in(0.1f, 1.3f);
            light.direction = glm::normalize(glm::vec3(in(-1, 1), in(-1, 1), in(-1, 1)) + 1e-3f);
        }
        const LightBounds b = lightBoundsInView(light, glm::mat4(1.0f));
        const glm::vec3 lo(bounds[0], bounds[1], bounds[2]), hi(bounds[3], bounds[4], bounds[5]);
        const glm::vec3 pad(kPad * (1.0f - lo.z));
        if (!lightTouchesBox(b, lo - pad, hi + pad)) continue;
        const uint32_t expected = boundingShapeTouchesBoxes(b, quarters, 4, kPad);
        ASSERT_EQ(quarterBoxesTouched(b, quarters, kPad), expected)
            << "trial " << trial << " shape " << int(b.shape) << " occupied " << occupied;
        ++compared;
        partial += expected != 0 && expected != occupied;
    }
    // Enough cases, and enough where some occupied quarter is missed, to mean something.
    EXPECT_GT(compared, 2000u);
    EXPECT_GT(partial, 200u);
}
