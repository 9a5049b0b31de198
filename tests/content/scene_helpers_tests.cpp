// Scene-file helpers a first game leans on: built-in plane/box/sphere meshes with a material,
// and a lookAt target instead of a hand-computed quaternion. Bad input names file and element.
#include <gtest/gtest.h>

#include <candela/ecs/transform.h>
#include <candela/ecs/transform_math.h>
#include <candela/ecs/view.h>

#include <cmath>
#include <map>
#include <string>

#include "candela/content/asset_cache.h"
#include "candela/content/builtin_meshes.h"
#include "candela/content/components/light.h"
#include "candela/content/components/mesh_instance.h"
#include "candela/content/components/name.h"
#include "candela/content/light_texture.h"
#include "candela/content/png_writer.h"
#include "candela/content/scene_file.h"
#include "candela/content/scene_instantiation.h"
#include "test_paths.h"

namespace candela::content {
namespace {

std::optional<SceneDocument> parse(const std::string& entities, Diagnostics& diagnostics) {
    const std::string text =
        R"({"format": "candela.scene", "version": 1, "entities": [)" + entities + "]}";
    return parseSceneJson(std::as_bytes(std::span(text)), "level.scene.json", diagnostics);
}

ecs::Vec3 forwardOf(const std::array<float, 4>& r) {
    return ecs::rotate(ecs::Quat{r[0], r[1], r[2], r[3]}, ecs::Vec3{0, 0, -1});
}

TEST(SceneHelpers, BuiltinMeshesAreUnitSizedWithOneGreyMaterial) {
    const Model& model = builtinMeshModel();
    ASSERT_EQ(model.meshes.size(), 3u);
    ASSERT_EQ(model.materials.size(), 1u);
    const Primitive& plane = model.meshes[int(BuiltinMesh::Plane)].primitives.at(0);
    const Primitive& box = model.meshes[int(BuiltinMesh::Box)].primitives.at(0);
    const Primitive& sphere = model.meshes[int(BuiltinMesh::Sphere)].primitives.at(0);
    EXPECT_FLOAT_EQ(plane.boundsMax[0] - plane.boundsMin[0], 1.0f);
    EXPECT_FLOAT_EQ(plane.boundsMax[1] - plane.boundsMin[1], 0.0f);
    EXPECT_FLOAT_EQ(box.boundsMax[1] - box.boundsMin[1], 1.0f);
    EXPECT_NEAR(sphere.boundsMax[1] - sphere.boundsMin[1], 1.0f, 1e-5f);
    for (const Mesh& mesh : model.meshes) {
        EXPECT_FALSE(mesh.primitives[0].indices.empty());
        EXPECT_EQ(mesh.primitives[0].material, 0);
    }
    EXPECT_EQ(builtinMeshFromName("sphere"), BuiltinMesh::Sphere);
    EXPECT_FALSE(builtinMeshFromName("cone"));
}

TEST(SceneHelpers, BuiltinMeshesWithAMaterialLoadSaveAndReload) {
    Diagnostics diagnostics;
    auto scene = parse(R"(
        {"name": "floor", "transform": {"scale": [20, 1, 20]},
         "mesh": {"builtin": "plane", "material": {"baseColorFactor": [0.2, 0.3, 0.4, 1]}}},
        {"name": "ball", "mesh": {"builtin": "sphere"}},
        {"name": "crate", "mesh": {"builtin": "box"}})",
                       diagnostics);
    ASSERT_TRUE(scene) << diagnostics.toString();
    EXPECT_FALSE(diagnostics.hasErrors()) << diagnostics.toString();
    ASSERT_TRUE(scene->entities[0].mesh);
    EXPECT_EQ(scene->entities[0].mesh->builtin, "plane");
    ASSERT_EQ(scene->entities[0].materialOverrides.size(), 1u);
    EXPECT_EQ(scene->entities[0].materialOverrides[0].primitive, 0);
    EXPECT_FLOAT_EQ(scene->entities[0].materialOverrides[0].material.baseColorFactor[2], 0.4f);

    ecs::Registry registry;
    AssetCache cache;
    instantiateScene(registry, *scene, "level.scene.json", cache, diagnostics);
    std::map<std::string, MeshInstance> meshes;
    registry.view<const Name, const MeshInstance>().each(
        [&](const Name& name, const MeshInstance& mesh) { meshes[name.value] = mesh; });
    ASSERT_EQ(meshes.size(), 3u);
    EXPECT_EQ(meshes["floor"].model, &builtinMeshModel());
    EXPECT_EQ(meshes["floor"].mesh, int(BuiltinMesh::Plane));
    EXPECT_EQ(meshes["ball"].mesh, int(BuiltinMesh::Sphere));
    EXPECT_EQ(meshes["crate"].mesh, int(BuiltinMesh::Box));

    // Saving writes the built-in name back, and the text loads into the same document.
    std::string error;
    const std::string text = sceneToJson(captureScene(registry), error);
    ASSERT_EQ(error, "");
    EXPECT_NE(text.find("\"builtin\": \"sphere\""), std::string::npos) << text;
    Diagnostics again;
    auto reloaded = parseSceneJson(std::as_bytes(std::span(text)), "saved.json", again);
    ASSERT_TRUE(reloaded) << again.toString();
    EXPECT_EQ(reloaded->entities[1].mesh->builtin, "sphere");
    ASSERT_EQ(reloaded->entities[0].materialOverrides.size(), 1u);
    EXPECT_EQ(reloaded->entities[0].materialOverrides[0].material.baseColorFactor,
              scene->entities[0].materialOverrides[0].material.baseColorFactor);
}

TEST(SceneHelpers, BadBuiltinMeshesNameTheFileAndTheElement) {
    Diagnostics diagnostics;
    auto scene = parse(R"(
        {"name": "a", "mesh": {"builtin": "cone"}},
        {"name": "b", "mesh": {"builtin": "box", "gltf": "x.glb"}},
        {"name": "c", "mesh": {}},
        {"name": "d", "mesh": {"builtin": "box", "material": {"roughnessFactor": "rough"}}})",
                       diagnostics);
    ASSERT_TRUE(scene);
    for (int i = 0; i < 4; ++i)
        EXPECT_FALSE(scene->entities[size_t(i)].mesh) << i;
    EXPECT_TRUE(diagnostics.mentions(
        "level.scene.json: /entities/0/mesh/builtin: error: 'cone' is not one of: plane, box, "
        "sphere"))
        << diagnostics.toString();
    EXPECT_TRUE(diagnostics.mentions("/entities/1/mesh/builtin: error: give \"gltf\" or"));
    EXPECT_TRUE(diagnostics.mentions("/entities/2/mesh/gltf: error: missing glTF path"));
    EXPECT_TRUE(diagnostics.mentions("/entities/3/mesh/material/roughnessFactor"));
}

TEST(SceneHelpers, LookAtPointsCamerasAndLightsAtTheTarget) {
    Diagnostics diagnostics;
    auto scene = parse(R"(
        {"name": "camera", "transform": {"translation": [0, 5, 5], "lookAt": [0, 0, 0]},
         "camera": {}},
        {"name": "spot", "transform": {"translation": [3, 4, -2], "lookAt": [-1, 0, 6]},
         "light": {"type": "spot", "lumens": 800}},
        {"name": "down", "transform": {"translation": [1, 9, 1], "lookAt": [1, 0, 1]},
         "light": {"type": "directional", "lux": 3}})",
                       diagnostics);
    ASSERT_TRUE(scene) << diagnostics.toString();
    EXPECT_FALSE(diagnostics.hasErrors()) << diagnostics.toString();
    const std::array<ecs::Vec3, 3> expected{ecs::Vec3{0, -5, -5}, ecs::Vec3{-4, -4, 8},
                                            ecs::Vec3{0, -1, 0}};
    for (size_t i = 0; i < expected.size(); ++i) {
        const ecs::Vec3 want = expected[i] * (1.0f / ecs::length(expected[i]));
        const ecs::Vec3 got = forwardOf(scene->entities[i].transform.rotation);
        EXPECT_NEAR(got.x, want.x, 1e-5f) << i;
        EXPECT_NEAR(got.y, want.y, 1e-5f) << i;
        EXPECT_NEAR(got.z, want.z, 1e-5f) << i;
        // Upright: the camera's +X stays horizontal.
        const auto& r = scene->entities[i].transform.rotation;
        EXPECT_NEAR(ecs::rotate(ecs::Quat{r[0], r[1], r[2], r[3]}, {1, 0, 0}).y, 0.0f, 1e-5f);
    }
}

TEST(SceneHelpers, BadLookAtNamesTheElement) {
    Diagnostics diagnostics;
    auto scene = parse(R"(
        {"name": "a", "transform": {"lookAt": [0, 0, 0]}},
        {"name": "b", "transform": {"rotation": [0, 0, 0, 1], "lookAt": [0, 0, 1]}},
        {"name": "c", "transform": {"translation": [1, 2, 3], "lookAt": [1, "x", 3]}})",
                       diagnostics);
    ASSERT_TRUE(scene);
    EXPECT_TRUE(diagnostics.mentions(
        "level.scene.json: /entities/0/transform/lookAt: error: the target is the entity's own "
        "position"))
        << diagnostics.toString();
    EXPECT_TRUE(diagnostics.mentions("/entities/1/transform/lookAt: error: give \"rotation\""));
    EXPECT_TRUE(diagnostics.mentions("/entities/2/transform/lookAt/1"));
    // A bad transform is dropped whole (the entity keeps the identity), as other bad values.
    EXPECT_EQ(scene->entities[2].transform.translation, (std::array<float, 3>{0, 0, 0}));
}

// Issue 15: a rect's "texture" is decoded when the scene is instantiated, relative to the scene
// file; an unreadable one is an error naming the file, the element, the light and the image, the
// rect stays (untextured), and saving writes the name back.
TEST(SceneHelpers, RectLightTexturesLoadAtInstantiationAndSaveBack) {
    const std::filesystem::path sceneFile = testing::tempPath("level.scene.json");
    const std::uint8_t texel[4] = {10, 200, 30, 255};
    ASSERT_EQ(writePng(sceneFile.parent_path() / "card.png", 1, 1, 4, texel), "");
    Diagnostics diagnostics;
    auto scene = parse(R"(
        {"name": "screen", "light": {"type": "rect", "width": 1.6, "height": 0.9,
                                     "texture": "card.png"}},
        {"name": "broken", "light": {"type": "rect", "texture": "gone.png"}})",
                       diagnostics);
    ASSERT_TRUE(scene) << diagnostics.toString();
    EXPECT_FALSE(diagnostics.hasErrors()) << diagnostics.toString();
    ecs::Registry registry;
    AssetCache cache;
    const auto entities = instantiateScene(registry, *scene, sceneFile, cache, diagnostics);
    ASSERT_EQ(entities.size(), 2u);
    const auto screen = findLightTexture(registry.get<Light>(entities[0]).texture);
    ASSERT_TRUE(screen);
    ASSERT_TRUE(screen->image);
    EXPECT_EQ(screen->image->rgba[1], 200);
    const Light& broken = registry.get<Light>(entities[1]);
    EXPECT_EQ(broken.type, LightType::Rect);
    ASSERT_TRUE(findLightTexture(broken.texture));
    EXPECT_FALSE(findLightTexture(broken.texture)->image);
    const std::string messages = diagnostics.toString();
    EXPECT_NE(messages.find("/entities/1/light/texture"), std::string::npos) << messages;
    EXPECT_NE(messages.find("'broken'"), std::string::npos) << messages;
    EXPECT_NE(messages.find("gone.png"), std::string::npos) << messages;
    EXPECT_EQ(messages.find("/entities/0/"), std::string::npos) << messages;

    std::string error;
    const std::string saved = sceneToJson(*scene, error);
    EXPECT_NE(saved.find("\"texture\": \"card.png\""), std::string::npos) << saved;
    EXPECT_NE(saved.find("\"texture\": \"gone.png\""), std::string::npos) << saved;
}

}  // namespace
}  // namespace candela::content
