// Bodies against closed forms: free fall, a resting stack, a bounce, a kinematic push and the
// interpolation of rendered poses between steps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "candela/ecs/hierarchy.h"
#include "candela/physics/physics_world.h"
#include "physics_test_support.h"

namespace candela::physics {
namespace {

using namespace test;
using content::ColliderShape;

PhysicsSettings exactSteps() {
    PhysicsSettings settings;
    settings.interpolate = false;  // entities show each step as it is
    return settings;
}

TEST(Motion, FallingSphereFollowsTheClosedFormOverTwoSeconds) {
    ecs::Registry registry;
    const ecs::Entity ball =
        addCollider(registry, {0, 100, 0}, shapeOf(ColliderShape::Sphere), dynamicBody());
    PhysicsWorld physics(registry, exactSteps());
    for (int i = 0; i < 120; ++i)
        physics.update(1.0 / 60.0);
    const double fallen = 100.0 - positionOf(registry, ball).y;
    const double closedForm = 0.5 * 9.81 * 2.0 * 2.0;  // 19.62 m
    EXPECT_NEAR(fallen, closedForm, 0.01 * closedForm);
    EXPECT_NEAR(registry.get<content::RigidBody>(ball).linearVelocity.y, -9.81f * 2.0f,
                0.01f * 19.62f);
    EXPECT_EQ(physics.counts().steps, 120u);
}

// A stack of `count` boxes of half size `half` and `mass` on the floor: after 5 s every box is
// within 1 cm of where it was put.
void expectStackStands(int count, ecs::Vec3 half, float mass) {
    ecs::Registry registry;
    addFloor(registry);
    content::Collider box = shapeOf(ColliderShape::Box);
    box.halfExtents = half;
    std::vector<ecs::Entity> boxes;
    for (int i = 0; i < count; ++i) {
        boxes.push_back(
            addCollider(registry, {0, half.y * float(2 * i + 1), 0}, box, dynamicBody(mass)));
    }
    PhysicsWorld physics(registry, exactSteps());
    for (int i = 0; i < 300; ++i)
        physics.update(1.0 / 60.0);
    for (int i = 0; i < count; ++i) {
        const ecs::Vec3 p = positionOf(registry, boxes[i]);
        SCOPED_TRACE("box " + std::to_string(i));
        EXPECT_NEAR(p.x, 0.0f, 0.01f);
        EXPECT_NEAR(p.z, 0.0f, 0.01f);
        EXPECT_NEAR(p.y, half.y * float(2 * i + 1), 0.01f);
    }
}

// The solver settings (physics_world.cpp) were tuned on these stacks and the bounce below...
TEST(Motion, StackOfTenBoxesStaysWithinACentimetreForFiveSeconds) {
    expectStackStands(10, {0.5f, 0.5f, 0.5f}, 1.0f);
}

TEST(Motion, StacksOfPlanksAndSmallBoxesStayWithinACentimetreForFiveSeconds) {
    expectStackStands(12, {1.0f, 0.1f, 0.4f}, 8.0f);
    expectStackStands(10, {0.1f, 0.1f, 0.1f}, 0.2f);
}

// ...and confirmed on scenes that played no part in the tuning. A pyramid of 15 boxes holds
// to 1 cm like the stacks:
TEST(Motion, PyramidOfFifteenBoxesStaysWithinACentimetreForFiveSeconds) {
    ecs::Registry registry;
    addFloor(registry);
    content::Collider brick = shapeOf(ColliderShape::Box);
    brick.halfExtents = ecs::Vec3{0.4f, 0.3f, 0.4f};
    std::vector<std::pair<ecs::Entity, ecs::Vec3>> placed;
    for (int row = 0; row < 5; ++row) {
        for (int i = 0; i < 5 - row; ++i) {
            const ecs::Vec3 at{0.81f * (float(i) - 0.5f * float(4 - row)), 0.3f + 0.6f * float(row),
                               0};
            placed.emplace_back(addCollider(registry, at, brick, dynamicBody(3.0f)), at);
        }
    }
    PhysicsWorld physics(registry, exactSteps());
    for (int i = 0; i < 300; ++i)
        physics.update(1.0 / 60.0);
    for (std::size_t i = 0; i < placed.size(); ++i) {
        const ecs::Vec3 p = positionOf(registry, placed[i].first);
        SCOPED_TRACE("brick " + std::to_string(i));
        EXPECT_NEAR(p.x, placed[i].second.x, 0.01f);
        EXPECT_NEAR(p.y, placed[i].second.y, 0.01f);
        EXPECT_NEAR(p.z, placed[i].second.z, 0.01f);
    }
}

// A column of eight upright cylinders holds less well: Bullet finds flat cylinder caps one GJK
// point at a time, and the drums wander 1-2 cm in 5 s (1.0 cm alone, docs/physics-speed-vs-
// error.md; 1.9 cm with the pyramid's bodies in the same world). What holds is that it stands.
TEST(Motion, ColumnOfEightCylindersStandsForFiveSeconds) {
    ecs::Registry registry;
    addFloor(registry);
    content::Collider drum = shapeOf(ColliderShape::Cylinder);
    drum.radius = 0.3f;
    drum.height = 0.6f;
    std::vector<ecs::Entity> drums;
    for (int i = 0; i < 8; ++i)
        drums.push_back(
            addCollider(registry, {0, 0.3f + 0.6f * float(i), 0}, drum, dynamicBody(1.5f)));
    PhysicsWorld physics(registry, exactSteps());
    for (int i = 0; i < 300; ++i)
        physics.update(1.0 / 60.0);
    for (int i = 0; i < 8; ++i) {
        const ecs::Vec3 p = positionOf(registry, drums[i]);
        SCOPED_TRACE("drum " + std::to_string(i));
        EXPECT_LT(std::hypot(p.x, p.z), 0.05f);
        EXPECT_NEAR(p.y, 0.3f + 0.6f * float(i), 0.01f);
    }
}

TEST(Motion, RestitutionHalfBouncesToAQuarterOfTheDropHeight) {
    ecs::Registry registry;
    addFloor(registry);  // restitution 0: the pair takes the ball's
    content::RigidBody rubber = dynamicBody();
    rubber.restitution = 0.5f;
    const float drop = 2.0f;  // metres from the ball's bottom to the floor
    const ecs::Entity ball =
        addCollider(registry, {0, 0.5f + drop, 0}, shapeOf(ColliderShape::Sphere), rubber);
    PhysicsWorld physics(registry, exactSteps());  // 60 Hz: the apex to within 1.4 mm
    bool bounced = false;
    float apex = 0;
    for (int i = 0; i < 60 * 2; ++i) {
        physics.step();
        const ecs::Vec3 p = positionOf(registry, ball);
        const float vy = registry.get<content::RigidBody>(ball).linearVelocity.y;
        if (!bounced && vy > 0) bounced = true;
        if (bounced) apex = std::max(apex, p.y - 0.5f);
        if (bounced && vy < 0) break;
    }
    ASSERT_TRUE(bounced);
    EXPECT_NEAR(apex, 0.25f * drop, 0.05f * 0.25f * drop);
}

TEST(Motion, KinematicBodyFollowsItsTransformAndPushesADynamicOne) {
    ecs::Registry registry;
    content::RigidBody pusher;
    pusher.type = content::BodyType::Kinematic;
    const ecs::Entity paddle =
        addCollider(registry, {-2, 0, 0}, shapeOf(ColliderShape::Box), pusher);
    content::RigidBody floating = dynamicBody();
    floating.gravityScale = 0;
    const ecs::Entity box = addCollider(registry, {0, 0, 0}, shapeOf(ColliderShape::Box), floating);
    PhysicsWorld physics(registry, exactSteps());
    for (int i = 0; i < 60; ++i) {
        registry.patch<ecs::LocalTransform>(paddle,
                                            [](ecs::LocalTransform& t) { t.position.x += 0.05f; });
        physics.update(1.0 / 60.0);
    }
    EXPECT_NEAR(physics.bodyState(paddle)->position.x, 1.0f, 1e-5f);
    EXPECT_GT(positionOf(registry, box).x, 1.0f + 0.9f);  // pushed ahead of the paddle
}

TEST(Motion, InterpolationShowsThePoseBetweenTheLastTwoSteps) {
    ecs::Registry registry;
    content::RigidBody moving = dynamicBody();
    moving.gravityScale = 0;
    moving.linearVelocity = {6, 0, 0};  // 0.1 m per 1/60 s step
    const ecs::Entity ball =
        addCollider(registry, {0, 0, 0}, shapeOf(ColliderShape::Sphere), moving);
    PhysicsWorld physics(registry);
    physics.update(1.0 / 60.0);  // one step: shows the step's start
    EXPECT_NEAR(positionOf(registry, ball).x, 0.0f, 1e-6f);
    physics.update(0.5 / 60.0);  // half way to the next step
    EXPECT_NEAR(positionOf(registry, ball).x, 0.05f, 1e-5f);
    EXPECT_NEAR(physics.bodyState(ball)->position.x, 0.1f, 1e-5f);
    EXPECT_EQ(physics.counts().steps, 1u);
    EXPECT_NEAR(physics.leftoverSeconds(), 0.5 / 60.0, 1e-12);
}

TEST(Motion, GameCodeTeleportsADynamicBodyAndSetsItsVelocity) {
    ecs::Registry registry;
    const ecs::Entity ball =
        addCollider(registry, {0, 10, 0}, shapeOf(ColliderShape::Sphere), dynamicBody());
    PhysicsWorld physics(registry, exactSteps());
    physics.update(1.0 / 60.0);
    registry.patch<ecs::LocalTransform>(ball, [](ecs::LocalTransform& t) {
        t.position = {5, 20, 0};
    });
    registry.patch<content::RigidBody>(ball, [](content::RigidBody& b) {
        b.linearVelocity = {0, 9.81f / 60.0f, 0};
    });
    physics.update(1.0 / 60.0);
    // Teleported, then one step: the upward velocity cancels the step's gravity.
    EXPECT_NEAR(positionOf(registry, ball).x, 5.0f, 1e-6f);
    EXPECT_NEAR(positionOf(registry, ball).y, 20.0f, 1e-4f);
}

TEST(Motion, ChildColliderFollowsItsParentAndStaysLocal) {
    ecs::Registry registry;
    const ecs::Entity parent = registry.create();
    registry.emplace<ecs::LocalTransform>(parent, ecs::LocalTransform{{10, 0, 0}, {}, {1, 1, 1}});
    registry.emplace<ecs::WorldTransform>(parent).matrix =
        registry.get<ecs::LocalTransform>(parent).matrix();
    const ecs::Entity ball =
        addCollider(registry, {0, 5, 0}, shapeOf(ColliderShape::Sphere), dynamicBody());
    ASSERT_EQ(ecs::setParent(registry, ball, parent), ecs::ReparentResult::Ok);
    PhysicsWorld physics(registry, exactSteps());
    physics.update(1.0 / 60.0);
    EXPECT_NEAR(physics.bodyState(ball)->position.x, 10.0f, 1e-6f);
    EXPECT_NEAR(positionOf(registry, ball).x, 0.0f, 1e-6f);  // local to the parent
    EXPECT_LT(positionOf(registry, ball).y, 5.0f);
}

}  // namespace
}  // namespace candela::physics

namespace candela::physics {
namespace {

// A 5 cm pellet at 300 m/s moves 5 m a step: without continuous collision it passes a 10 cm
// wall between two steps; with it, the wall stops it.
TEST(Motion, ContinuousCollisionStopsAFastPelletAtAThinWall) {
    for (const bool continuous : {false, true}) {
        SCOPED_TRACE(continuous);
        ecs::Registry registry;
        content::Collider wall = test::shapeOf(content::ColliderShape::Box);
        wall.halfExtents = ecs::Vec3{0.05f, 5, 5};
        test::addCollider(registry, {10, 0, 0}, wall);
        content::Collider pellet = test::shapeOf(content::ColliderShape::Sphere);
        pellet.radius = 0.05f;
        content::RigidBody fast = test::dynamicBody(0.01f);
        fast.gravityScale = 0;
        fast.linearVelocity = {300, 0, 0};
        fast.continuousCollision = continuous;
        const ecs::Entity shot = test::addCollider(registry, {0, 0, 0}, pellet, fast);
        PhysicsWorld physics(registry);
        for (int i = 0; i < 10; ++i)
            physics.update(1.0 / 60.0);
        if (continuous) {
            EXPECT_LT(physics.bodyState(shot)->position.x, 10.0f);
        } else {
            EXPECT_GT(physics.bodyState(shot)->position.x, 10.0f) << "the test's premise";
        }
    }
}

}  // namespace
}  // namespace candela::physics
