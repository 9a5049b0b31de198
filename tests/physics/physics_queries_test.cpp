// Raycasts, sweeps and overlaps against analytic answers.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "candela/content/builtin_meshes.h"
#include "candela/content/components/mesh_instance.h"
#include "candela/physics/physics_queries.h"
#include "physics_test_support.h"

namespace candela::physics {
namespace {

using namespace test;
using content::ColliderShape;

constexpr float kTolerance = 1e-4f;  // metres (issue 46)

struct RayCase {
    const char* name;
    ecs::Vec3 origin, direction;
    float distance;  // the analytic answer
    ecs::Vec3 normal;
};

// Shapes placed away from the origin and turned, so the test covers the body's pose.
const ecs::Vec3 kAt{3, 2, -4};
const ecs::Quat kQuarterTurn = ecs::Quat::fromAxisAngle({0, 1, 0}, std::numbers::pi_v<float> / 2);

void expectRays(ecs::Registry& registry, ecs::Entity target, std::initializer_list<RayCase> cases) {
    PhysicsWorld physics(registry);
    physics.sync();
    for (const RayCase& c : cases) {
        SCOPED_TRACE(c.name);
        const std::optional<Hit> hit = raycast(physics, kAt + c.origin, c.direction, 100.0f);
        ASSERT_TRUE(hit.has_value());
        EXPECT_EQ(hit->entity, target);
        EXPECT_NEAR(hit->distance, c.distance, kTolerance);
        EXPECT_NEAR(hit->normal.x, c.normal.x, 1e-4f);
        EXPECT_NEAR(hit->normal.y, c.normal.y, 1e-4f);
        EXPECT_NEAR(hit->normal.z, c.normal.z, 1e-4f);
    }
}

TEST(Raycast, SphereWithinATenthOfAMillimetre) {
    ecs::Registry registry;
    const ecs::Entity e = addCollider(registry, kAt, shapeOf(ColliderShape::Sphere), {},
                                      kQuarterTurn, {2, 2, 2});  // radius 1
    const float offset = 0.6f;
    expectRays(registry, e,
               {{"head on", {-5, 0, 0}, {1, 0, 0}, 4.0f, {-1, 0, 0}},
                {"off centre",
                 {-5, offset, 0},
                 {2, 0, 0},
                 5.0f - std::sqrt(1 - offset * offset),
                 {-std::sqrt(1 - offset * offset), offset, 0}},
                {"from above", {0, 7, 0}, {0, -1, 0}, 6.0f, {0, 1, 0}}});
}

TEST(Raycast, TurnedBoxWithinATenthOfAMillimetre) {
    ecs::Registry registry;
    content::Collider box = shapeOf(ColliderShape::Box);
    box.halfExtents = ecs::Vec3{0.5f, 1.0f, 2.0f};
    // A quarter turn about Y: the long local Z axis lies along world X.
    const ecs::Entity e = addCollider(registry, kAt, box, {}, kQuarterTurn);
    expectRays(registry, e,
               {{"along the long side", {-10, 0, 0}, {1, 0, 0}, 8.0f, {-1, 0, 0}},
                {"across", {0, 0, 10}, {0, 0, -1}, 9.5f, {0, 0, 1}},
                {"down", {1.5f, 5, 0.2f}, {0, -1, 0}, 4.0f, {0, 1, 0}}});
}

TEST(Raycast, CapsuleAndCylinderWithinATenthOfAMillimetre) {
    ecs::Registry registry;
    content::Collider capsule = shapeOf(ColliderShape::Capsule);  // r 0.5, 2 m end to end
    const ecs::Entity c = addCollider(registry, kAt, capsule);
    expectRays(registry, c,
               {{"side", {-5, 0.3f, 0}, {1, 0, 0}, 4.5f, {-1, 0, 0}},
                {"top", {0, 5, 0}, {0, -1, 0}, 4.0f, {0, 1, 0}},
                {"shoulder", {-5, 0.8f, 0}, {1, 0, 0}, 5.0f - 0.4f, {-0.8f, 0.6f, 0}}});
    ecs::Registry other;
    content::Collider cylinder = shapeOf(ColliderShape::Cylinder);               // r 0.5, 1 m tall
    const ecs::Entity y = addCollider(other, kAt, cylinder, {}, {}, {2, 3, 2});  // r 1, 3 m
    expectRays(other, y,
               {{"side", {-5, 1.2f, 0}, {1, 0, 0}, 4.0f, {-1, 0, 0}},
                {"cap", {0.5f, 5, 0.5f}, {0, -1, 0}, 3.5f, {0, 1, 0}},
                {"under", {0, -5, 0.9f}, {0, 1, 0}, 3.5f, {0, -1, 0}}});
}

TEST(Raycast, HullAndTriangleMeshOfTheBuiltinBoxWithinATenthOfAMillimetre) {
    const content::Model& builtin = content::builtinMeshModel();
    const content::MeshInstance boxMesh{
        &builtin, static_cast<std::int32_t>(content::BuiltinMesh::Box), {}};
    for (const ColliderShape shape : {ColliderShape::ConvexHull, ColliderShape::TriangleMesh}) {
        SCOPED_TRACE(shape == ColliderShape::ConvexHull ? "hull" : "triangle mesh");
        ecs::Registry registry;
        const ecs::Entity e = addCollider(registry, kAt, shapeOf(shape), {}, {}, {4, 2, 2});
        registry.emplace<content::MeshInstance>(e, boxMesh);
        expectRays(registry, e,
                   {{"side", {-6, 0.3f, 0.1f}, {1, 0, 0}, 4.0f, {-1, 0, 0}},
                    {"top", {1.1f, 5, -0.2f}, {0, -1, 0}, 4.0f, {0, 1, 0}}});
    }
}

TEST(Raycast, MissesFiltersAndAllHits) {
    ecs::Registry registry;
    const ecs::Entity near = addCollider(registry, {2, 0, 0}, shapeOf(ColliderShape::Box));
    const ecs::Entity far = addCollider(registry, {6, 0, 0}, shapeOf(ColliderShape::Sphere));
    content::Collider zone = shapeOf(ColliderShape::Box);
    zone.trigger = true;
    const ecs::Entity trigger = addCollider(registry, {4, 0, 0}, zone);
    PhysicsWorld physics(registry);
    physics.sync();
    EXPECT_FALSE(raycast(physics, {0, 0, 0}, {-1, 0, 0}, 100).has_value());
    EXPECT_FALSE(raycast(physics, {0, 0, 0}, {1, 0, 0}, 1.4f).has_value());  // too short
    EXPECT_FALSE(raycast(physics, {0, 0, 0}, {0, 0, 0}, 10).has_value());    // no direction
    EXPECT_EQ(raycast(physics, {0, 0, 0}, {1, 0, 0}, 100)->entity, near);
    QueryFilter skipNear;
    skipNear.ignore = near;
    EXPECT_EQ(raycast(physics, {0, 0, 0}, {1, 0, 0}, 100, skipNear)->entity, far);
    const std::vector<Hit> all = raycastAll(physics, {0, 0, 0}, {1, 0, 0}, 100);
    ASSERT_EQ(all.size(), 2u);
    EXPECT_EQ(all[0].entity, near);
    EXPECT_EQ(all[1].entity, far);
    QueryFilter withTriggers;
    withTriggers.triggers = true;
    const std::vector<Hit> everything =
        raycastAll(physics, {0, 0, 0}, {1, 0, 0}, 100, withTriggers);
    ASSERT_EQ(everything.size(), 3u);
    EXPECT_EQ(everything[1].entity, trigger);
    // A ray that starts inside a collider does not hit it.
    EXPECT_EQ(raycast(physics, {2, 0, 0}, {1, 0, 0}, 100)->entity, far);
}

TEST(Sweep, SphereStopsWhereItFirstTouches) {
    ecs::Registry registry;
    const ecs::Entity wall = addCollider(registry, {5, 0, 0}, shapeOf(ColliderShape::Box));
    PhysicsWorld physics(registry);
    physics.sync();
    const std::optional<Hit> hit = sweep(physics, sphereOf(0.25f), {}, {0, 0, 0}, {10, 0, 0});
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->entity, wall);
    EXPECT_NEAR(hit->distance, 5.0f - 0.5f - 0.25f, 1e-3f);
    EXPECT_NEAR(hit->normal.x, -1.0f, 1e-3f);
    EXPECT_FALSE(sweep(physics, sphereOf(0.25f), {}, {0, 2, 0}, {10, 2, 0}).has_value());
}

TEST(Overlap, FindsWhatTheShapeTouchesInCreationOrder) {
    ecs::Registry registry;
    const ecs::Entity a = addCollider(registry, {0, 0, 0}, shapeOf(ColliderShape::Box));
    addCollider(registry, {10, 0, 0}, shapeOf(ColliderShape::Box));
    const ecs::Entity c = addCollider(registry, {1.5f, 0, 0}, shapeOf(ColliderShape::Sphere));
    PhysicsWorld physics(registry);
    physics.sync();
    const std::vector<ecs::Entity> found = overlap(physics, sphereOf(0.8f), {0.9f, 0, 0});
    ASSERT_EQ(found.size(), 2u);
    EXPECT_EQ(found[0], a);
    EXPECT_EQ(found[1], c);
    EXPECT_TRUE(overlap(physics, sphereOf(0.5f), {5, 0, 0}).empty());
}

}  // namespace
}  // namespace candela::physics
