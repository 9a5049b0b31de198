// The two silent failures a first game hit: an entity made in code with a mesh but without a
// WorldTransform was never drawn, and a light whose lumens changed without markChanged<Light>
// never updated. SceneWorld::updateTransforms (run every frame) now fixes both, and names the
// forgotten markChanged once.
#include <gtest/gtest.h>

#include <string>

#include "candela/content/builtin_meshes.h"
#include "candela/content/components/light.h"
#include "candela/content/components/mesh_instance.h"
#include "candela/ecs/transform.h"
#include "candela/ecs/view.h"
#include "candela/runtime/light_table.h"
#include "candela/runtime/scene_world.h"

using namespace candela;

namespace {

// What frame extraction draws: entities with a WorldTransform and a MeshInstance.
int drawnAt(ecs::Registry& registry, ecs::Entity wanted, ecs::Vec3& position) {
    int found = 0;
    registry.view<const ecs::WorldTransform, const content::MeshInstance>().each(
        [&](ecs::Entity e, const ecs::WorldTransform& world, const content::MeshInstance&) {
            if (e != wanted) return;
            ++found;
            position = {world.matrix(0, 3), world.matrix(1, 3), world.matrix(2, 3)};
        });
    return found;
}

content::MeshInstance builtinSphere() {
    return {&content::builtinMeshModel(), int(content::BuiltinMesh::Sphere), ""};
}

}  // namespace

TEST(Footguns, AMeshMadeInCodeWithoutAWorldTransformIsDrawn) {
    runtime::SceneWorld world;
    auto& registry = world.registry;
    const ecs::Entity placed = registry.create();
    ecs::LocalTransform at;
    at.position = {1.0f, 2.0f, 3.0f};
    registry.emplace<ecs::LocalTransform>(placed, at);
    registry.emplace<content::MeshInstance>(placed, builtinSphere());
    const ecs::Entity bare = registry.create();  // not even a LocalTransform
    registry.emplace<content::MeshInstance>(bare, builtinSphere());

    world.updateTransforms();
    ecs::Vec3 p{};
    ASSERT_EQ(drawnAt(registry, placed, p), 1);
    EXPECT_EQ(p, (ecs::Vec3{1.0f, 2.0f, 3.0f}));
    ASSERT_EQ(drawnAt(registry, bare, p), 1);
    EXPECT_EQ(p, (ecs::Vec3{0.0f, 0.0f, 0.0f}));

    // And it follows later moves like any other entity.
    registry.patch<ecs::LocalTransform>(placed, [](ecs::LocalTransform& t) { t.position.x = 5; });
    world.updateTransforms();
    ASSERT_EQ(drawnAt(registry, placed, p), 1);
    EXPECT_EQ(p.x, 5.0f);
}

TEST(Footguns, SpawnGivesAnEntityEverythingItNeedsToBeDrawn) {
    runtime::SceneWorld world;
    ecs::LocalTransform at;
    at.position = {0.0f, 4.0f, 0.0f};
    const ecs::Entity e = world.spawn("ball", at);
    world.registry.emplace<content::MeshInstance>(e, builtinSphere());
    world.updateTransforms();
    ecs::Vec3 p{};
    ASSERT_EQ(drawnAt(world.registry, e, p), 1);
    EXPECT_EQ(p.y, 4.0f);
}

TEST(Footguns, ALightChangedWithoutMarkChangedStillUpdatesAndIsNamedOnce) {
    runtime::SceneWorld world;
    auto& registry = world.registry;
    const ecs::Entity lamp = world.spawn("lamp");
    registry.emplace<content::Light>(lamp, content::Light{});
    runtime::LightTable table(registry);
    world.updateTransforms();
    table.update();
    ASSERT_EQ(table.lights().size(), 1u);
    EXPECT_EQ(table.lights()[0].light.lumens, 800.0f);

    registry.get<content::Light>(lamp).lumens = 2500.0f;  // no markChanged<Light>
    testing::internal::CaptureStderr();
    world.updateTransforms();
    const std::string warned = testing::internal::GetCapturedStderr();
    table.update();
    EXPECT_EQ(table.lights()[0].light.lumens, 2500.0f);
    EXPECT_EQ(table.changedSlots(), std::vector<uint32_t>{0});
    EXPECT_NE(warned.find("the Light of entity 'lamp' was changed without markChanged<Light>()"),
              std::string::npos)
        << warned;

    // Once per entity; a marked change is silent and a quiet frame changes nothing.
    registry.get<content::Light>(lamp).lumens = 100.0f;
    testing::internal::CaptureStderr();
    world.updateTransforms();
    registry.patch<content::Light>(lamp, [](content::Light& l) { l.lumens = 50.0f; });
    world.updateTransforms();
    world.updateTransforms();
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
    table.update();
    EXPECT_EQ(table.lights()[0].light.lumens, 50.0f);
    world.updateTransforms();
    table.update();
    EXPECT_TRUE(table.changedSlots().empty());
}

TEST(Footguns, ATransformMovedWithoutMarkChangedStillPropagates) {
    runtime::SceneWorld world;
    const ecs::Entity e = world.spawn("crate");
    world.registry.emplace<content::MeshInstance>(e, builtinSphere());
    world.updateTransforms();
    world.registry.get<ecs::LocalTransform>(e).position = {0.0f, 0.0f, -7.0f};
    testing::internal::CaptureStderr();
    world.updateTransforms();
    const std::string warned = testing::internal::GetCapturedStderr();
    ecs::Vec3 p{};
    ASSERT_EQ(drawnAt(world.registry, e, p), 1);
    EXPECT_EQ(p.z, -7.0f);
    EXPECT_NE(warned.find("LocalTransform of entity 'crate'"), std::string::npos) << warned;

    // Turned off (a world too large to compare every frame), the rule is the caller's again.
    world.checkUnmarkedChanges = false;
    world.registry.get<ecs::LocalTransform>(e).position = {0.0f, 0.0f, 3.0f};
    world.updateTransforms();
    ASSERT_EQ(drawnAt(world.registry, e, p), 1);
    EXPECT_EQ(p.z, -7.0f);
}
