// Compound bodies: colliders on children without a RigidBody are parts of their nearest
// ancestor's body, move with it, and name themselves in raycasts.
#include <gtest/gtest.h>

#include "candela/ecs/hierarchy.h"
#include "candela/physics/physics_queries.h"
#include "candela/physics/physics_world.h"
#include "physics_test_support.h"

namespace candela::physics {
namespace {

using namespace test;
using content::ColliderShape;

// A dumbbell: a body entity without a collider of its own and two unit boxes 2 m apart as its
// children (the body at x = 0, the boxes at x = -1 and x = +1).
struct Dumbbell {
    ecs::Entity body, left, right;
};

Dumbbell addDumbbell(ecs::Registry& registry, ecs::Vec3 at) {
    Dumbbell d;
    d.body = registry.create();
    registry.emplace<ecs::LocalTransform>(d.body, ecs::LocalTransform{at, {}, {1, 1, 1}});
    registry.emplace<ecs::WorldTransform>(d.body);
    registry.emplace<content::RigidBody>(d.body, dynamicBody(2.0f));
    d.left = addCollider(registry, {-1, 0, 0}, shapeOf(ColliderShape::Box));
    d.right = addCollider(registry, {1, 0, 0}, shapeOf(ColliderShape::Box));
    EXPECT_EQ(ecs::setParent(registry, d.left, d.body), ecs::ReparentResult::Ok);
    EXPECT_EQ(ecs::setParent(registry, d.right, d.body), ecs::ReparentResult::Ok);
    return d;
}

TEST(CompoundBody, ChildCollidersArePartsOfTheirAncestorsBody) {
    ecs::Registry registry;
    addFloor(registry);
    const Dumbbell d = addDumbbell(registry, {0, 3, 0});
    PhysicsSettings settings;
    settings.interpolate = false;
    PhysicsWorld physics(registry, settings);
    for (int i = 0; i < 120; ++i)
        physics.update(1.0 / 60.0);
    EXPECT_EQ(physics.counts().bodies, 2u) << "the floor and one compound, not three bodies";
    // Resting flat on both boxes: the body's origin half a box above the floor.
    EXPECT_NEAR(positionOf(registry, d.body).y, 0.5f, 0.01f);
    EXPECT_NEAR(positionOf(registry, d.body).x, 0.0f, 0.01f);
    // The parts keep their local offsets; their world transforms follow the body.
    EXPECT_EQ(positionOf(registry, d.left).x, -1.0f);
    // A ray down onto the right box names the right box.
    const auto hit = raycast(physics, {1.2f, 5, 0}, {0, -1, 0}, 10);
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->entity, d.right);
    EXPECT_NEAR(hit->point.y, 1.0f, 0.01f);
}

TEST(CompoundBody, ABodyWithItsOwnColliderAndPartsFallsAsOne) {
    ecs::Registry registry;
    addFloor(registry);
    // A sphere body with a box part hanging 1 m below it, off to the side.
    const ecs::Entity ball =
        addCollider(registry, {0, 4, 0}, shapeOf(ColliderShape::Sphere), dynamicBody());
    const ecs::Entity foot = addCollider(registry, {0, -1, 0}, shapeOf(ColliderShape::Box));
    ASSERT_EQ(ecs::setParent(registry, foot, ball), ecs::ReparentResult::Ok);
    PhysicsWorld physics(registry);
    physics.update(1.0 / 60.0);
    EXPECT_EQ(physics.counts().bodies, 2u);
    for (int i = 0; i < 180; ++i)
        physics.update(1.0 / 60.0);
    // The foot, not the ball, stands on the floor: the ball's centre rests 1.5 m up.
    EXPECT_NEAR(positionOf(registry, ball).y, 1.5f, 0.02f);
    // Taking the part away leaves the ball alone, which then falls to the floor.
    registry.remove<content::Collider>(foot);
    for (int i = 0; i < 120; ++i)
        physics.update(1.0 / 60.0);
    EXPECT_NEAR(positionOf(registry, ball).y, 0.5f, 0.02f);
}

}  // namespace
}  // namespace candela::physics
