// The CPU light assignment's SIMD frustum pre-pass (issue 22): it must change no list, only
// skip lights the per-light walk would drop anyway. Runs on the CPU alone (analytic floor).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "bench/analytic_floor.h"
#include "candela/ecs/job_system.h"

using namespace candela::render;
using namespace candela::render::bench;
using candela::content::LightType;

namespace {

// Every light shape, scattered all around the camera (behind, beside, straddling the near
// plane, huge), plus lights placed just outside and just inside each screen edge.
std::vector<LightInstance> lightsAllAround(size_t count, uint32_t seed, const glm::mat4& view,
                                           const ClusterGrid& grid) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> x(-150.0f, 150.0f), y(-2.0f, 12.0f), z(-200.0f, 60.0f);
    std::uniform_real_distribution<float> radius(0.3f, 6.0f), unit(0.0f, 1.0f);
    std::vector<LightInstance> lights;
    auto add = [&](const glm::vec3& p, float r) {
        LightInstance l;
        l.light.type = LightType::Point;
        l.light.lumens = 500.0f;
        l.light.attenuationRadius = r;
        l.position = p;
        lights.push_back(l);
        return &lights.back();
    };
    for (size_t i = 0; i < count; ++i) {
        LightInstance& l = *add({x(rng), y(rng), z(rng)}, radius(rng));
        switch (i % 6) {
            case 1:
                l.light.sourceRadius = 0.3f * unit(rng);
                break;
            case 2:
                l.light.sourceLength = 0.2f + 6.0f * unit(rng);
                l.tubeAxis =
                    glm::normalize(glm::vec3(unit(rng) - 0.5f, unit(rng) - 0.5f, unit(rng) - 0.5f));
                break;
            case 3:
            case 4:
                l.light.type = LightType::Spot;
                l.light.outerConeAngle = 0.1f + 1.45f * unit(rng);  // narrow and wide cones
                l.light.innerConeAngle = 0.5f * l.light.outerConeAngle;
                l.direction =
                    glm::normalize(glm::vec3(unit(rng) - 0.5f, unit(rng) - 0.5f, unit(rng) - 0.5f));
                break;
            default:
                break;
        }
    }
    // Edge cases in view space: spheres whose surface sits a hair outside or inside each
    // side plane and the near plane, at several depths.
    const glm::mat4 toWorld = glm::inverse(view);
    const float edges[4][2] = {{grid.columnTangent.front(), 0.0f},
                               {grid.columnTangent.back(), 0.0f},
                               {0.0f, grid.rowTangent.front()},
                               {0.0f, grid.rowTangent.back()}};
    for (float depth : {0.5f, 4.0f, 30.0f, 150.0f}) {
        for (const auto& edge : edges) {
            for (float offset : {-1e-3f, -1e-5f, 0.0f, 1e-5f, 1e-3f}) {
                const float r = 0.05f * depth;
                // Plane through the camera containing the screen edge; move the centre out
                // along its normal by r (+ offset).
                glm::vec3 onEdge(edge[0] * depth, edge[1] * depth, -depth);
                glm::vec3 outward = edge[1] == 0.0f
                                        ? glm::normalize(glm::vec3(1.0f, 0.0f, edge[0])) *
                                              (edge[0] > 0.0f ? 1.0f : -1.0f)
                                        : glm::normalize(glm::vec3(0.0f, 1.0f, edge[1])) *
                                              (edge[1] > 0.0f ? 1.0f : -1.0f);
                glm::vec3 center = onEdge + outward * (r + offset * r);
                add(glm::vec3(toWorld * glm::vec4(center, 1.0f)), r);
            }
        }
        for (float offset : {-1e-3f, 0.0f, 1e-3f}) {  // far side just before the near plane
            const float r = 0.02f;
            glm::vec3 center(0.0f, 0.0f, -(grid.nearPlane - r + offset * r));
            add(glm::vec3(toWorld * glm::vec4(center, 1.0f)), r);
        }
    }
    add(glm::vec3(toWorld * glm::vec4(0.0f, 0.0f, 5.0f, 1.0f)), 1000.0f);  // covers all
    LightInstance sun;
    sun.light.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(-0.3f, -1.0f, -0.2f));
    lights.push_back(sun);
    return lights;
}

struct Lists {
    std::vector<uint32_t> indices;
    std::vector<uint32_t> ranges;
    uint32_t inFrustum = 0;
    uint32_t local = 0;
};

Lists assign(const AnalyticFloorView& floor, const std::vector<LightInstance>& lights,
             bool withOccupancy, bool prepass, candela::ecs::JobSystem* jobs) {
    Lists lists;
    lists.ranges.assign(size_t(floor.grid.clusterCount()) * 2, 0);
    LightAssignment out;
    out.frustumPrepass = prepass;
    assignLights(floor.grid, lights, floor.view,
                 withOccupancy ? floor.occupancy() : ClusterOccupancy{}, jobs, lists.ranges, out);
    lists.indices = out.lightIndices;
    lists.inFrustum = out.lightsInFrustum;
    for (const LightInstance& l : lights)
        lists.local += l.light.type != LightType::Directional;
    return lists;
}

}  // namespace

TEST(LightFrustumPrepass, ListsAreIdenticalWithAndWithoutIt) {
    candela::ecs::JobSystem jobs;
    for (uint32_t width : {320u, 1280u}) {
        const AnalyticFloorView floor = analyticFloorView(width, width * 9 / 16, 100.0f);
        const std::vector<LightInstance> lights =
            lightsAllAround(3000, width, floor.view, floor.grid);
        for (bool withOccupancy : {true, false}) {
            Lists without = assign(floor, lights, withOccupancy, false, &jobs);
            Lists with = assign(floor, lights, withOccupancy, true, &jobs);
            SCOPED_TRACE(testing::Message() << width << " px, occupancy " << withOccupancy);
            EXPECT_EQ(with.indices, without.indices);
            EXPECT_EQ(with.ranges, without.ranges);
            EXPECT_GT(without.indices.size(), 1000u);  // the scene does light the floor
            // Without the pre-pass every local light reaches the walk; with it, the ~40% of
            // these (scattered all around the camera) behind or beside the view do not.
            EXPECT_EQ(without.inFrustum, without.local);
            EXPECT_LT(with.inFrustum, without.local * 3 / 4);
            EXPECT_GT(with.inFrustum, without.local / 4);
            std::printf(
                "%u px, occupancy %d: %u of %u local lights pass the pre-pass, %zu list "
                "entries\n",
                width, int(withOccupancy), with.inFrustum, with.local, with.indices.size());
        }
    }
}

TEST(LightFrustumPrepass, SingleThreadedGivesTheSameLists) {
    candela::ecs::JobSystem jobs;
    const AnalyticFloorView floor = analyticFloorView(640, 360, 100.0f);
    const std::vector<LightInstance> lights = lightsAllAround(1500, 7, floor.view, floor.grid);
    Lists threaded = assign(floor, lights, true, true, &jobs);
    Lists single = assign(floor, lights, true, true, nullptr);
    Lists reference = assign(floor, lights, true, false, nullptr);
    EXPECT_EQ(threaded.indices, reference.indices);
    EXPECT_EQ(single.indices, reference.indices);
    EXPECT_EQ(single.ranges, reference.ranges);
}
