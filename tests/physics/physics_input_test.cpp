// Bad input: a clear message naming the entity and the field; the body clamped or skipped,
// never a crash or a NaN transform.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "candela/content/components/mesh_instance.h"
#include "candela/content/components/name.h"
#include "candela/content/model.h"
#include "candela/physics/physics_world.h"
#include "physics_test_support.h"

namespace candela::physics {
namespace {

using namespace test;
using content::ColliderShape;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

bool finite(ecs::Vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

TEST(PhysicsInput, NegativeMassIsClampedWithAMessageNamingEntityAndField) {
    ecs::Registry registry;
    const ecs::Entity e =
        addCollider(registry, {0, 5, 0}, shapeOf(ColliderShape::Box), dynamicBody(-3.0f));
    registry.emplace<content::Name>(e, content::Name{"crate"});
    PhysicsWorld physics(registry);
    physics.update(1.0 / 60.0);
    physics.update(1.0 / 60.0);
    const std::string said = physics.diagnostics().toString();
    EXPECT_NE(said.find("\"crate\""), std::string::npos) << said;
    EXPECT_NE(said.find("rigidBody.mass"), std::string::npos) << said;
    EXPECT_EQ(physics.diagnostics().messages.size(), 1u) << "said once, not every frame";
    EXPECT_EQ(physics.counts().activeBodies, 1u);  // simulated at 1 kg
}

TEST(PhysicsInput, NaNVelocityBecomesZero) {
    ecs::Registry registry;
    content::RigidBody body = dynamicBody();
    body.linearVelocity = {kNaN, 1, 0};
    body.angularVelocity = {0, std::numeric_limits<float>::infinity(), 0};
    const ecs::Entity e = addCollider(registry, {0, 5, 0}, shapeOf(ColliderShape::Sphere), body);
    PhysicsWorld physics(registry);
    for (int i = 0; i < 10; ++i)
        physics.update(1.0 / 60.0);
    EXPECT_TRUE(physics.diagnostics().mentions("rigidBody.linearVelocity"));
    EXPECT_TRUE(physics.diagnostics().mentions("rigidBody.angularVelocity"));
    EXPECT_TRUE(finite(positionOf(registry, e)));
    EXPECT_TRUE(finite(registry.get<content::RigidBody>(e).linearVelocity));
}

TEST(PhysicsInput, ZeroSizeAndDegenerateCollidersMakeNoBody) {
    ecs::Registry registry;
    content::Collider flat = shapeOf(ColliderShape::Box);
    flat.halfExtents = ecs::Vec3{1, 0, 1};
    addCollider(registry, {0, 0, 0}, flat, dynamicBody());
    content::Collider point = shapeOf(ColliderShape::Sphere);
    point.radius = 0.0f;
    addCollider(registry, {0, 0, 0}, point);
    content::Collider nanCapsule = shapeOf(ColliderShape::Capsule);
    nanCapsule.height = kNaN;
    addCollider(registry, {0, 0, 0}, nanCapsule);
    addCollider(registry, {0, 0, 0}, shapeOf(ColliderShape::Box), dynamicBody(), {}, {1, 0, 1});
    addCollider(registry, {0, 0, 0}, shapeOf(ColliderShape::ConvexHull));  // no mesh
    PhysicsWorld physics(registry);
    physics.update(1.0 / 60.0);
    EXPECT_EQ(physics.counts().bodies, 0u);
    const std::string said = physics.diagnostics().toString();
    EXPECT_NE(said.find("collider.halfExtents"), std::string::npos) << said;
    EXPECT_NE(said.find("collider.radius"), std::string::npos) << said;
    EXPECT_NE(said.find("collider.height"), std::string::npos) << said;
    EXPECT_NE(said.find("scale"), std::string::npos) << said;
    EXPECT_NE(said.find("needs a mesh"), std::string::npos) << said;
}

TEST(PhysicsInput, TriangleMeshSkipsTrianglesWithNaNVertices) {
    content::Model model;
    content::Primitive& quad = model.meshes.emplace_back().primitives.emplace_back();
    quad.positions = {{-5, 0, -5}, {5, 0, -5}, {5, 0, 5}, {-5, 0, 5}, {kNaN, 0, 0}};
    quad.indices = {0, 2, 1, 0, 3, 2, 0, 4, 1};
    ecs::Registry registry;
    const ecs::Entity ground =
        addCollider(registry, {0, 0, 0}, shapeOf(ColliderShape::TriangleMesh));
    registry.emplace<content::MeshInstance>(ground, content::MeshInstance{&model, 0, {}});
    const ecs::Entity ball =
        addCollider(registry, {0, 2, 0}, shapeOf(ColliderShape::Sphere), dynamicBody());
    PhysicsWorld physics(registry);
    for (int i = 0; i < 120; ++i)
        physics.update(1.0 / 60.0);
    EXPECT_TRUE(physics.diagnostics().mentions("1 triangles with non-finite vertices skipped"))
        << physics.diagnostics().toString();
    EXPECT_NEAR(positionOf(registry, ball).y, 0.5f, 0.02f);  // resting on the two good ones
}

TEST(PhysicsInput, ColliderWithoutTransformAndNaNTransformsAreRefused) {
    ecs::Registry registry;
    const ecs::Entity bare = registry.create();
    registry.emplace<content::Collider>(bare, shapeOf(ColliderShape::Sphere));
    const ecs::Entity ball =
        addCollider(registry, {0, 5, 0}, shapeOf(ColliderShape::Sphere), dynamicBody());
    PhysicsWorld physics(registry);
    physics.update(1.0 / 60.0);
    EXPECT_TRUE(physics.diagnostics().mentions("needs a LocalTransform"));
    EXPECT_EQ(physics.counts().bodies, 1u);
    // Game code writes a NaN: the body keeps its last good pose.
    registry.patch<ecs::LocalTransform>(ball, [](ecs::LocalTransform& t) { t.position.y = kNaN; });
    physics.update(1.0 / 60.0);
    EXPECT_TRUE(physics.diagnostics().mentions("transform: not finite"));
    EXPECT_TRUE(std::isfinite(physics.bodyState(ball)->position.y));
}

TEST(PhysicsInput, BadStepAndDeltaAreRefused) {
    ecs::Registry registry;
    PhysicsSettings settings;
    settings.stepSeconds = 0;
    PhysicsWorld physics(registry, settings);
    EXPECT_EQ(physics.settings().stepSeconds, 1.0 / 60.0);
    physics.update(std::nan(""));
    physics.update(-1.0);
    EXPECT_EQ(physics.counts().steps, 0u);
    EXPECT_TRUE(physics.diagnostics().mentions("deltaSeconds"));
}

}  // namespace
}  // namespace candela::physics
