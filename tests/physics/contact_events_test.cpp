// Contact and trigger events: each phase once per touch, in a deterministic order.
#include <gtest/gtest.h>

#include <algorithm>

#include "candela/physics/physics_world.h"
#include "physics_test_support.h"

namespace candela::physics {
namespace {

using namespace test;
using content::ColliderShape;

struct PhaseCounts {
    int begin = 0, stay = 0, end = 0;
    void add(ContactPhase phase) {
        (phase == ContactPhase::Begin ? begin : phase == ContactPhase::Stay ? stay : end) += 1;
    }
};

TEST(ContactEvents, TriggerSeesABodyPassOnceWithBeginAndEnd) {
    ecs::Registry registry;
    content::Collider zone = shapeOf(ColliderShape::Box);
    zone.trigger = true;
    const ecs::Entity trigger = addCollider(registry, {0, 0, 0}, zone);
    content::RigidBody moving = dynamicBody();
    moving.gravityScale = 0;
    moving.linearVelocity = {3, 0, 0};
    const ecs::Entity ball =
        addCollider(registry, {-3, 0, 0}, shapeOf(ColliderShape::Sphere), moving);
    PhysicsWorld physics(registry);
    PhaseCounts counts;
    for (int i = 0; i < 120; ++i) {
        physics.update(1.0 / 60.0);
        for (const TriggerEvent& e : physics.events().triggers) {
            EXPECT_EQ(e.trigger, trigger);
            EXPECT_EQ(e.other, ball);
            counts.add(e.phase);
        }
        EXPECT_TRUE(physics.events().contacts.empty());  // a trigger never collides
    }
    EXPECT_EQ(counts.begin, 1);
    EXPECT_EQ(counts.end, 1);
    EXPECT_GT(counts.stay, 10);
    // It passed through: nothing stopped it.
    EXPECT_NEAR(registry.get<content::RigidBody>(ball).linearVelocity.x, 3.0f, 1e-5f);
}

TEST(ContactEvents, StaticTriggerSeesAKinematicBody) {
    ecs::Registry registry;
    content::Collider zone = shapeOf(ColliderShape::Sphere);
    zone.trigger = true;
    addCollider(registry, {0, 0, 0}, zone);
    content::RigidBody carried;
    carried.type = content::BodyType::Kinematic;
    const ecs::Entity player =
        addCollider(registry, {5, 0, 0}, shapeOf(ColliderShape::Capsule), carried);
    PhysicsWorld physics(registry);
    physics.update(1.0 / 60.0);
    EXPECT_TRUE(physics.events().triggers.empty());
    registry.patch<ecs::LocalTransform>(player,
                                        [](ecs::LocalTransform& t) { t.position.x = 0.5f; });
    physics.update(1.0 / 60.0);
    ASSERT_EQ(physics.events().triggers.size(), 1u);
    EXPECT_EQ(physics.events().triggers[0].phase, ContactPhase::Begin);
}

TEST(ContactEvents, LandingBoxBeginsThenStaysWithUpwardNormalAndImpulse) {
    ecs::Registry registry;
    const ecs::Entity floor = addFloor(registry);
    const ecs::Entity box =
        addCollider(registry, {0, 1.0f, 0}, shapeOf(ColliderShape::Box), dynamicBody(2.0f));
    PhysicsWorld physics(registry);
    PhaseCounts counts;
    ContactEvent first;
    for (int i = 0; i < 120; ++i) {
        physics.update(1.0 / 60.0);
        for (const ContactEvent& e : physics.events().contacts) {
            if (e.phase == ContactPhase::Begin && counts.begin == 0) first = e;
            counts.add(e.phase);
        }
    }
    EXPECT_EQ(counts.begin, 1);
    EXPECT_EQ(counts.end, 0);
    EXPECT_GT(counts.stay, 50);
    // The registry's resource holds the same events.
    const auto* shared = registry.resources().tryGet<PhysicsEvents>();
    ASSERT_NE(shared, nullptr);
    ASSERT_EQ(shared->contacts.size(), physics.events().contacts.size());
    EXPECT_EQ(shared->contacts[0].b, box);
    EXPECT_EQ(first.a, floor);  // made first
    EXPECT_EQ(first.b, box);
    // From b (the box) towards a (the floor): down.
    EXPECT_NEAR(first.normal.y, -1.0f, 1e-3f);
    EXPECT_GT(first.impulse, 0.0f);
}

TEST(ContactEvents, DestroyedBodyEndsItsContacts) {
    ecs::Registry registry;
    addFloor(registry);
    const ecs::Entity box =
        addCollider(registry, {0, 0.5f, 0}, shapeOf(ColliderShape::Box), dynamicBody());
    PhysicsWorld physics(registry);
    for (int i = 0; i < 10; ++i)
        physics.update(1.0 / 60.0);
    registry.destroy(box);
    physics.update(1.0 / 60.0);
    ASSERT_EQ(physics.events().contacts.size(), 1u);
    EXPECT_EQ(physics.events().contacts[0].phase, ContactPhase::End);
    EXPECT_EQ(physics.events().contacts[0].b, box);
    physics.update(1.0 / 60.0);
    EXPECT_TRUE(physics.events().contacts.empty());
}

TEST(ContactEvents, LayersThatDoNotMaskEachOtherPassThrough) {
    ecs::Registry registry;
    content::Collider ground = shapeOf(ColliderShape::Box);
    ground.halfExtents = ecs::Vec3{10, 0.5f, 10};
    ground.layer = 1u << 0;
    addCollider(registry, {0, -0.5f, 0}, ground);
    content::Collider ghost = shapeOf(ColliderShape::Sphere);
    ghost.layer = 1u << 1;
    ghost.mask = 1u << 1;  // sees only its own layer
    const ecs::Entity ball = addCollider(registry, {0, 1, 0}, ghost, dynamicBody());
    PhysicsWorld physics(registry);
    for (int i = 0; i < 60; ++i)
        physics.update(1.0 / 60.0);
    EXPECT_LT(positionOf(registry, ball).y, -1.0f);  // fell through the floor
}

}  // namespace
}  // namespace candela::physics
