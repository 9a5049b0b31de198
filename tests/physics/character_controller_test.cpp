// The character controller: walks, climbs a 0.3 m step, stops at a wall, stays on a walkable
// slope, refuses a steep one, jumps and lands.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "candela/physics/character_controller.h"
#include "candela/physics/physics_world.h"
#include "physics_test_support.h"

namespace candela::physics {
namespace {

using namespace test;
using content::ColliderShape;

ecs::Entity addBox(ecs::Registry& registry, ecs::Vec3 centre, ecs::Vec3 half,
                   ecs::Quat rotation = {}) {
    content::Collider box = shapeOf(ColliderShape::Box);
    box.halfExtents = half;
    return addCollider(registry, centre, box, std::nullopt, rotation);
}

ecs::Entity addWalker(ecs::Registry& registry, ecs::Vec3 feet) {
    const ecs::Entity e = registry.create();
    CharacterController c;
    registry.emplace<ecs::LocalTransform>(
        e, ecs::LocalTransform{
               {feet.x, feet.y + 0.5f * c.height + c.skinWidth, feet.z}, {}, {1, 1, 1}});
    registry.emplace<CharacterController>(e, c);
    return e;
}

float feetOf(const ecs::Registry& registry, ecs::Entity e) {
    const auto& c = registry.get<CharacterController>(e);
    return positionOf(registry, e).y - 0.5f * c.height;
}

void walk(PhysicsWorld& physics, ecs::Registry& registry, ecs::Entity e, ecs::Vec3 velocity,
          int frames) {
    for (int i = 0; i < frames; ++i) {
        registry.get<CharacterController>(e).desiredVelocity = velocity;
        physics.update(1.0 / 60.0);
    }
}

TEST(CharacterController, ClimbsAThirtyCentimetreStepAndStopsAtAWall) {
    ecs::Registry registry;
    addFloor(registry);
    addBox(registry, {6, 0.15f, 0}, {4, 0.15f, 4});  // a 0.3 m step from x = 2 on
    addBox(registry, {8.5f, 2, 0}, {0.5f, 2, 4});    // a wall from x = 8
    const ecs::Entity walker = addWalker(registry, {0, 0, 0});
    PhysicsWorld physics(registry);
    walk(physics, registry, walker, {0, 0, 0}, 10);
    EXPECT_TRUE(registry.get<CharacterController>(walker).grounded);
    EXPECT_NEAR(feetOf(registry, walker), 0.02f, 0.01f);
    walk(physics, registry, walker, {3, 0, 0}, 60);  // 3 m: onto the step
    EXPECT_GT(positionOf(registry, walker).x, 2.5f);
    EXPECT_NEAR(feetOf(registry, walker), 0.32f, 0.01f);
    EXPECT_TRUE(registry.get<CharacterController>(walker).grounded);
    walk(physics, registry, walker, {3, 0, 0}, 180);  // into the wall
    const float radius = registry.get<CharacterController>(walker).radius;
    EXPECT_NEAR(positionOf(registry, walker).x, 8.0f - radius - 0.02f, 0.01f);
    EXPECT_NEAR(positionOf(registry, walker).z, 0.0f, 1e-4f);
}

TEST(CharacterController, DoesNotClimbAStepTallerThanItsStepHeight) {
    ecs::Registry registry;
    addFloor(registry);
    addBox(registry, {6, 0.25f, 0}, {4, 0.25f, 4});  // 0.5 m > 0.35 m
    const ecs::Entity walker = addWalker(registry, {0, 0, 0});
    PhysicsWorld physics(registry);
    walk(physics, registry, walker, {3, 0, 0}, 120);
    EXPECT_LT(positionOf(registry, walker).x, 2.0f - 0.3f + 1e-3f);
    EXPECT_NEAR(feetOf(registry, walker), 0.02f, 0.01f);
}

TEST(CharacterController, WalksUpAWalkableSlopeButNotASteepOne) {
    const float pi = std::numbers::pi_v<float>;
    for (const float degrees : {30.0f, 60.0f}) {
        SCOPED_TRACE(degrees);
        ecs::Registry registry;
        addFloor(registry);
        const float a = degrees * pi / 180;
        // A ramp rising along +x from x = 2, its top face tilted by `a`.
        const ecs::Quat tilt = ecs::Quat::fromAxisAngle({0, 0, 1}, a);
        addBox(registry, {2 + 5 * std::cos(a), 5 * std::sin(a) - 0.5f * std::cos(a), 0},
               {5, 0.5f, 4}, tilt);
        const ecs::Entity walker = addWalker(registry, {0, 0, 0});
        PhysicsWorld physics(registry);
        walk(physics, registry, walker, {2, 0, 0}, 150);  // 5 m
        if (degrees < 45) {
            EXPECT_GT(feetOf(registry, walker), 0.5f) << "it climbed";
            EXPECT_TRUE(registry.get<CharacterController>(walker).grounded);
        } else {
            EXPECT_LT(feetOf(registry, walker), 0.35f) << "at most a step up";
            EXPECT_LT(positionOf(registry, walker).x, 2.5f);
        }
    }
}

TEST(CharacterController, JumpsAndLandsAtTheBallisticHeight) {
    ecs::Registry registry;
    addFloor(registry);
    const ecs::Entity walker = addWalker(registry, {0, 0, 0});
    PhysicsWorld physics(registry);
    walk(physics, registry, walker, {0, 0, 0}, 5);
    registry.get<CharacterController>(walker).jump = true;
    float apex = 0;
    bool landed = false;
    for (int i = 0; i < 120 && !landed; ++i) {
        physics.update(1.0 / 60.0);
        apex = std::max(apex, feetOf(registry, walker));
        landed = i > 5 && registry.get<CharacterController>(walker).grounded;
    }
    const float v = registry.get<CharacterController>(walker).jumpSpeed;
    EXPECT_TRUE(landed);
    EXPECT_NEAR(apex - 0.02f, v * v / (2 * 9.81f), 0.05f * v * v / (2 * 9.81f));
    EXPECT_NEAR(feetOf(registry, walker), 0.02f, 0.01f);
}

TEST(CharacterController, WalksOffALedgeAndFalls) {
    ecs::Registry registry;
    addBox(registry, {0, -0.5f, 0}, {2, 0.5f, 2});  // a platform; nothing below
    const ecs::Entity walker = addWalker(registry, {0, 0, 0});
    PhysicsWorld physics(registry);
    walk(physics, registry, walker, {3, 0, 0}, 60);  // 3 m: past the edge at x = 2
    walk(physics, registry, walker, {0, 0, 0}, 30);
    EXPECT_FALSE(registry.get<CharacterController>(walker).grounded);
    EXPECT_LT(feetOf(registry, walker), -1.0f);
}

}  // namespace
}  // namespace candela::physics

namespace candela::physics {
namespace {

TEST(CharacterController, WithAKinematicCapsuleItEntersTriggersAndIgnoresItself) {
    ecs::Registry registry;
    addFloor(registry);
    content::Collider zone = test::shapeOf(content::ColliderShape::Box);
    zone.trigger = true;
    const ecs::Entity coin = test::addCollider(registry, {3, 1, 0}, zone);
    const ecs::Entity walker = addWalker(registry, {0, 0, 0});
    content::Collider capsule = test::shapeOf(content::ColliderShape::Capsule);
    capsule.radius = 0.3f;
    capsule.height = 1.8f;
    registry.emplace<content::Collider>(walker, capsule);
    content::RigidBody carried;
    carried.type = content::BodyType::Kinematic;
    registry.emplace<content::RigidBody>(walker, carried);
    PhysicsWorld physics(registry);
    int begins = 0;
    for (int i = 0; i < 120; ++i) {
        registry.get<CharacterController>(walker).desiredVelocity = {2, 0, 0};
        physics.update(1.0 / 60.0);
        for (const TriggerEvent& e : physics.events().triggers)
            begins += e.trigger == coin && e.other == walker && e.phase == ContactPhase::Begin;
    }
    EXPECT_EQ(begins, 1);
    EXPECT_GT(test::positionOf(registry, walker).x, 3.9f) << "its own capsule never blocked it";
    EXPECT_NEAR(feetOf(registry, walker), 0.02f, 0.01f);
}

}  // namespace
}  // namespace candela::physics
