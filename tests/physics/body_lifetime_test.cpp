// Bodies live and die with their entities and components: no stale handle, no leak (the
// sanitizer build checks Bullet's objects too).
#include <gtest/gtest.h>

#include "candela/physics/physics_world.h"
#include "physics_test_support.h"

namespace candela::physics {
namespace {

using namespace test;
using content::ColliderShape;

TEST(BodyLifetime, TenThousandEntityChurnLeavesExactlyTheLiveBodies) {
    ecs::Registry registry;
    addFloor(registry);
    PhysicsWorld physics(registry);
    std::vector<ecs::Entity> alive;
    std::uint32_t made = 0;
    for (int round = 0; round < 10; ++round) {
        for (int i = 0; i < 1000; ++i) {
            const float x = float((made * 7) % 50) - 25.0f;
            const float z = float((made * 13) % 50) - 25.0f;
            const auto shape = static_cast<ColliderShape>(made % 4);  // the four primitives
            alive.push_back(
                addCollider(registry, {x, 1.0f + float(i % 5), z}, shapeOf(shape), dynamicBody()));
            ++made;
        }
        physics.update(1.0 / 60.0);
        // Destroy every other entity, and take the collider off a few more.
        std::vector<ecs::Entity> kept;
        for (std::size_t i = 0; i < alive.size(); ++i) {
            if (i % 2 == 0) {
                registry.destroy(alive[i]);
            } else if (i % 7 == 0) {
                registry.remove<content::Collider>(alive[i]);
            } else {
                kept.push_back(alive[i]);
            }
        }
        alive = kept;
        physics.update(1.0 / 60.0);
        EXPECT_EQ(physics.counts().bodies, alive.size() + 1);  // + the floor
    }
    EXPECT_EQ(made, 10000u);
    for (const ecs::Entity e : alive)
        registry.destroy(e);
    physics.update(1.0 / 60.0);
    EXPECT_EQ(physics.counts().bodies, 1u);
    EXPECT_EQ(physics.counts().shapes, 1u);
}

TEST(BodyLifetime, ChangedColliderRemakesTheBodyInPlace) {
    ecs::Registry registry;
    const ecs::Entity e = addCollider(registry, {0, 0, 0}, shapeOf(ColliderShape::Sphere));
    PhysicsWorld physics(registry);
    physics.sync();
    registry.patch<content::Collider>(e, [](content::Collider& c) { c.radius = 2.0f; });
    registry.emplace<content::RigidBody>(e, dynamicBody());
    physics.update(1.0 / 60.0);
    EXPECT_EQ(physics.counts().bodies, 1u);
    EXPECT_EQ(physics.counts().activeBodies, 1u);
    registry.remove<content::RigidBody>(e);  // static again
    physics.update(1.0 / 60.0);
    EXPECT_EQ(physics.counts().activeBodies, 0u);
}

TEST(BodyLifetime, RestingBodiesFallAsleepAndWakeWhenTouched) {
    ecs::Registry registry;
    addFloor(registry);
    const ecs::Entity box =
        addCollider(registry, {0, 0.5f, 0}, shapeOf(ColliderShape::Box), dynamicBody());
    PhysicsSettings settings;
    settings.interpolate = false;
    PhysicsWorld physics(registry, settings);
    for (int i = 0; i < 180; ++i)
        physics.update(1.0 / 60.0);
    EXPECT_TRUE(registry.get<content::RigidBody>(box).sleeping);
    EXPECT_EQ(physics.counts().activeBodies, 0u);
    registry.patch<content::RigidBody>(box, [](content::RigidBody& b) {
        b.linearVelocity = {0, 3, 0};
    });
    physics.update(1.0 / 60.0);
    EXPECT_FALSE(registry.get<content::RigidBody>(box).sleeping);
    EXPECT_GT(positionOf(registry, box).y, 0.5f);
}

}  // namespace
}  // namespace candela::physics
