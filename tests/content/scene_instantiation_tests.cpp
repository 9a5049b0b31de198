#include <gtest/gtest.h>

#include <candela/ecs/hierarchy.h>
#include <candela/ecs/transform.h>
#include <candela/ecs/transform_propagation.h>

#include <cstring>
#include <filesystem>

#include "candela/content/components/mesh_instance.h"
#include "candela/content/components/scene_components.h"
#include "candela/content/gltf_loader.h"
#include "candela/content/model_instantiation.h"
#include "candela/content/scene_instantiation.h"

namespace candela::content {
namespace {

TEST(SceneInstantiation, GltfNodesBecomeEntitiesWithHierarchyAndWorldTransforms) {
    Diagnostics diagnostics;
    const auto path = std::filesystem::path(CANDELA_SHARED_ASSETS) / "models/Box/Box.glb";
    auto model = loadGltf(path, diagnostics);
    ASSERT_TRUE(model) << diagnostics.toString();
    ecs::Registry registry;
    const auto entities =
        instantiateModel(registry, *model, ecs::kNullEntity, "models/Box/Box.glb");
    ASSERT_EQ(entities.size(), 2u) << "parents before children";
    const ecs::Entity root = entities[0];
    const ecs::Entity child = entities[1];
    EXPECT_EQ(ecs::parentOf(registry, child), root);
    ASSERT_TRUE(registry.has<MeshInstance>(child));
    EXPECT_EQ(registry.get<MeshInstance>(child).model, &*model);
    EXPECT_EQ(registry.get<MeshInstance>(child).gltfPath, "models/Box/Box.glb");
    EXPECT_FALSE(registry.has<MeshInstance>(root));
    ecs::propagateTransforms(registry);
    // Box's root node rotates the Z-up box to Y-up: the child's world matrix must include it.
    const ecs::Mat4 world = registry.get<ecs::WorldTransform>(child).matrix;
    const ecs::Mat4 local = registry.get<ecs::LocalTransform>(child).matrix();
    EXPECT_NE(std::memcmp(&world, &local, sizeof(ecs::Mat4)), 0)
        << "the parent's rotation reached the child";
}

TEST(SceneInstantiation, SceneToRegistryAndBackIsIdentical) {
    SceneDocument scene;
    for (int i = 0; i < 4; ++i) {
        SceneEntity& e = scene.entities.emplace_back();
        e.name = "e" + std::to_string(i);
        e.transform.translation = {0.1f * static_cast<float>(i), 1.0f / 3.0f, 2.0f};
    }
    scene.entities[0].parent = 2;  // parent later in the list
    scene.entities[1].parent = 0;
    scene.entities[1].mesh = MeshReference{"models/Box/Box.glb", 0};
    scene.entities[2].mesh = MeshReference{"models/missing.glb", 1};  // kept, though unloadable
    scene.entities[2].light = Light{};
    scene.entities[2].light->lumens = 321.0f;
    scene.entities[3].camera = Camera{};
    scene.entities[3].sky = Sky{"sky.exr", 2.0f};
    scene.entities[3].gameDataJson = R"({"hp":10})";
    MaterialOverride override;
    override.primitive = 1;
    override.material.roughnessFactor = 0.123f;
    scene.entities[1].materialOverrides.push_back(override);

    ecs::Registry registry;
    AssetCache cache;
    Diagnostics diagnostics;
    const auto sceneFile = std::filesystem::path(CANDELA_SHARED_ASSETS) / "level.scene.json";
    const auto entities = instantiateScene(registry, scene, sceneFile, cache, diagnostics);
    ASSERT_EQ(entities.size(), 4u);
    EXPECT_EQ(ecs::parentOf(registry, entities[0]), entities[2]);
    ASSERT_NE(registry.get<MeshInstance>(entities[1]).model, nullptr) << diagnostics.toString();
    EXPECT_EQ(registry.get<MeshInstance>(entities[2]).model, nullptr);
    EXPECT_TRUE(diagnostics.mentions("missing.glb"));
    const SceneDocument captured = captureScene(registry);
    std::string a;
    std::string b;
    EXPECT_EQ(sceneToJson(captured, a), sceneToJson(scene, b));
    EXPECT_TRUE(a.empty() && b.empty());
}

// Issue 44: a scene file's material override naming texture 99 (or 2^31 - 1) of a model with
// fewer was bound to the slot's fallback without a word. It is a warning naming the override's
// slot; the entity and its override still load.
TEST(SceneInstantiation, AnOverrideNamingAMissingTextureIsAWarningNamingTheSlot) {
    SceneDocument scene;
    SceneEntity& e = scene.entities.emplace_back();
    e.mesh = MeshReference{"models/Box/Box.glb", 0};  // no textures
    MaterialOverride override;
    override.material.baseColorTexture.texture = 99;
    override.material.clearcoatNormalTexture.texture = 2147483647;
    e.materialOverrides.push_back(override);
    e.materialOverrides.push_back(MaterialOverride{});  // untextured: nothing to say

    ecs::Registry registry;
    AssetCache cache;
    Diagnostics diagnostics;
    const auto sceneFile = std::filesystem::path(CANDELA_SHARED_ASSETS) / "level.scene.json";
    const auto entities = instantiateScene(registry, scene, sceneFile, cache, diagnostics);
    ASSERT_EQ(entities.size(), 1u);
    ASSERT_NE(registry.get<MeshInstance>(entities[0]).model, nullptr) << diagnostics.toString();
    const std::string messages = diagnostics.toString();
    EXPECT_NE(messages.find("/entities/0/materialOverrides/0/material/baseColorTexture: warning: "
                            "texture 99 is not one of the model's 0 textures"),
              std::string::npos)
        << messages;
    EXPECT_NE(messages.find("/entities/0/materialOverrides/0/material/clearcoatNormalTexture"),
              std::string::npos)
        << messages;
    EXPECT_EQ(messages.find("/materialOverrides/1"), std::string::npos) << messages;
    EXPECT_EQ(registry.get<MaterialOverrides>(entities[0]).overrides.size(), 2u);
}

}  // namespace
}  // namespace candela::content
