// RigidBody and Collider (issue 46) in scene files: the interface form reads as written, every
// field survives a save and a load, absurd values are clamped with a warning and sizes that
// leave a collider no shape drop it with an error naming the file and the element.
#include <gtest/gtest.h>

#include <string>

#include "candela/content/scene_file.h"
#include "scene_component_checks.h"

namespace candela::content {
namespace {

constexpr const char* kFile = "physics.scene.json";

std::optional<SceneDocument> parse(const std::string& text, Diagnostics& diagnostics) {
    return testing::parseScene(text, kFile, diagnostics);
}

TEST(PhysicsComponents, TheIssueFormReadsAsWritten) {
    Diagnostics diagnostics;
    auto loaded = parse(
        testing::sceneWithComponent(
            "collider", R"({"shape": "sphere"})",
            R"("rigidBody": {"type": "dynamic", "mass": 2.5, "friction": 0.25, "restitution": 0.5}, )"),
        diagnostics);
    ASSERT_TRUE(loaded) << diagnostics.toString();
    EXPECT_TRUE(diagnostics.messages.empty()) << diagnostics.toString();
    const SceneEntity& e = loaded->entities.at(0);
    ASSERT_TRUE(e.rigidBody && e.collider);
    EXPECT_EQ(e.rigidBody->type, BodyType::Dynamic);
    EXPECT_EQ(e.rigidBody->mass, 2.5f);
    EXPECT_EQ(e.rigidBody->friction, 0.25f);
    EXPECT_EQ(e.rigidBody->restitution, 0.5f);
    EXPECT_EQ(e.collider->shape, ColliderShape::Sphere);
    EXPECT_FALSE(e.collider->radius) << "no size: fits the builtin sphere";
    EXPECT_FALSE(e.collider->trigger);
}

TEST(PhysicsComponents, TriggerAndExplicitSizesRead) {
    Diagnostics diagnostics;
    auto loaded = parse(
        testing::sceneWithComponent(
            "collider",
            R"({"shape": "box", "halfExtents": [1, 0.5, 2], "trigger": true, "layer": 4, "mask": 5})"),
        diagnostics);
    ASSERT_TRUE(loaded && loaded->entities.at(0).collider) << diagnostics.toString();
    const Collider& c = *loaded->entities[0].collider;
    EXPECT_TRUE(c.trigger);
    ASSERT_TRUE(c.halfExtents);
    EXPECT_EQ(c.halfExtents->z, 2.0f);
    EXPECT_EQ(c.layer, 4u);
    EXPECT_EQ(c.mask, 5u);
    EXPECT_FALSE(loaded->entities[0].rigidBody) << "no rigid body: static";
}

TEST(PhysicsComponents, EveryFieldRoundTripsThroughASceneFile) {
    RigidBody body;
    body.type = BodyType::Kinematic;
    body.mass = 3.25f;
    body.friction = 0.8f;
    body.restitution = 0.125f;
    body.linearDamping = 0.1f;
    body.angularDamping = 0.2f;
    body.gravityScale = -0.5f;
    body.linearVelocity = {1, -2, 3.5f};
    body.angularVelocity = {0.25f, 0, -1};
    body.canSleep = false;
    body.continuousCollision = true;
    Collider capsule;
    capsule.shape = ColliderShape::Capsule;
    capsule.radius = 0.3f;
    capsule.height = 1.75f;
    capsule.layer = 1u << 3;
    capsule.mask = 0xfu;
    Collider hull;
    hull.shape = ColliderShape::ConvexHull;
    SceneDocument scene;
    scene.entities.emplace_back().rigidBody = body;
    scene.entities.back().collider = capsule;
    scene.entities.emplace_back().collider = hull;
    auto loaded = testing::savedAndLoaded(scene, kFile);
    ASSERT_TRUE(loaded);
    EXPECT_EQ(loaded->entities.at(0).rigidBody, body);
    EXPECT_EQ(loaded->entities.at(0).collider, capsule);
    EXPECT_EQ(loaded->entities.at(1).collider, hull);
    EXPECT_FALSE(loaded->entities.at(1).rigidBody);
}

TEST(PhysicsComponents, AbsurdBodyValuesAreClampedWithAWarning) {
    Diagnostics diagnostics;
    auto loaded = parse(testing::sceneWithComponent(
                            "collider", R"({"shape": "box"})",
                            R"("rigidBody": {"mass": -4, "restitution": 3, "friction": -1}, )"),
                        diagnostics);
    ASSERT_TRUE(loaded && loaded->entities.at(0).rigidBody) << diagnostics.toString();
    const RigidBody& b = *loaded->entities[0].rigidBody;
    EXPECT_EQ(b.mass, 1.0f);
    EXPECT_EQ(b.restitution, 1.0f);
    EXPECT_EQ(b.friction, 0.0f);
    const std::string text = diagnostics.toString();
    for (const char* element : {"/entities/0/rigidBody/mass", "/entities/0/rigidBody/restitution",
                                "/entities/0/rigidBody/friction"}) {
        EXPECT_NE(text.find(element), std::string::npos) << text;
    }
    EXPECT_EQ(diagnostics.count(Severity::Error), 0u) << text;
}

TEST(PhysicsComponents, ShapelessCollidersAreErrorsNamingTheFileAndTheElement) {
    const auto collider = [](const std::string& json) {
        return testing::sceneWithComponent("collider", json);
    };
    testing::expectEachComponentIsRejected(
        kFile,
        {
            {collider(R"({"shape": "sphere", "radius": 0})"), "/entities/0/collider/radius",
             "positive"},
            {collider(R"({"shape": "box", "halfExtents": [1, -1, 1]})"),
             "/entities/0/collider/halfExtents", "positive"},
            {collider(R"({"shape": "capsule", "height": -2})"), "/entities/0/collider/height",
             "positive"},
            {collider(R"({"shape": "cone"})"), "/entities/0/collider/shape", "not one of"},
            {collider(R"({"radius": 1})"), "/entities/0/collider/shape", "shape"},
            {collider(R"({"shape": "box", "layer": -1})"), "/entities/0/collider/layer",
             "out of range"},
        },
        [](const SceneEntity& e) { return e.collider.has_value(); });
}

TEST(PhysicsComponents, RigidBodyWithoutColliderWarns) {
    Diagnostics diagnostics;
    auto loaded =
        parse(testing::sceneWithComponent("rigidBody", R"({"type": "dynamic"})"), diagnostics);
    ASSERT_TRUE(loaded);
    EXPECT_TRUE(diagnostics.mentions("without a \"collider\"")) << diagnostics.toString();
}

}  // namespace
}  // namespace candela::content
