// The editor model without a window: edit commands, undo/redo, selection, saving.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

#include "candela/content/asset_cache.h"
#include "candela/content/component_validation.h"
#include "candela/content/components/mesh_instance.h"
#include "candela/content/components/name.h"
#include "candela/content/model.h"
#include "candela/content/procedural_mesh.h"
#include "candela/content/scene_file.h"
#include "candela/content/scene_instantiation.h"
#include "candela/ecs/hierarchy.h"
#include "candela/ecs/transform.h"
#include "model/edit_validation.h"
#include "model/editor_scene.h"
#include "model/material_editing.h"
#include "model/property_edits.h"
#include "model/set_component_command.h"
#include "model/structure_commands.h"

namespace candela::editor {
namespace {

namespace fs = std::filesystem;

// floor (mesh reference) / lamp (point light) -> bulb (child) / camera
content::SceneDocument testDocument() {
    content::SceneDocument doc;
    content::SceneEntity& floor = doc.entities.emplace_back();
    floor.name = "floor";
    floor.mesh = content::MeshReference{"models/floor.glb", 0};
    content::SceneEntity& lamp = doc.entities.emplace_back();
    lamp.name = "lamp";
    lamp.transform.translation = {0, 3, 0};
    lamp.light = content::Light{};
    lamp.light->lumens = 800.0f;
    content::SceneEntity& bulb = doc.entities.emplace_back();
    bulb.name = "bulb";
    bulb.parent = 1;
    bulb.light = content::Light{};
    bulb.light->sourceRadius = 0.1f;
    content::SceneEntity& camera = doc.entities.emplace_back();
    camera.name = "camera";
    camera.camera = content::Camera{};
    return doc;
}

class EditorModel : public ::testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() /
              ("candela_editor_model_" +
               std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir / "saved");
        source = dir / "level.scene.json";
        ASSERT_EQ(content::saveSceneFile(source, testDocument()), "");
        content::Diagnostics diagnostics;  // the missing floor model is reported, not fatal
        std::optional<content::SceneDocument> doc = content::loadSceneFile(source, diagnostics);
        ASSERT_TRUE(doc);
        content::instantiateScene(registry, *doc, source, cache, diagnostics);
        scene = std::make_unique<EditorScene>(registry, source);
    }
    void TearDown() override { fs::remove_all(dir); }

    ecs::Entity named(const std::string& name) { return scene->findByName(name); }
    float lumens(const std::string& name) {
        return registry.get<content::Light>(named(name)).lumens;
    }
    bool setLumens(const std::string& name, float value, uint64_t mergeKey = 0) {
        content::Light light = registry.get<content::Light>(named(name));
        light.lumens = value;
        return scene->execute(setComponent(*scene, named(name), light, "Set Light"), mergeKey);
    }
    content::SceneDocument saveAndLoad(const fs::path& path) {
        EXPECT_EQ(scene->save(path), "");
        content::Diagnostics diagnostics;
        std::optional<content::SceneDocument> doc = content::loadSceneFile(path, diagnostics);
        EXPECT_TRUE(doc) << path;
        return doc ? *doc : content::SceneDocument{};
    }
    static const content::SceneEntity* entityNamed(const content::SceneDocument& doc,
                                                   const std::string& name) {
        for (const content::SceneEntity& e : doc.entities) {
            if (e.name == name) return &e;
        }
        return nullptr;
    }

    fs::path dir;
    fs::path source;
    ecs::Registry registry;
    content::AssetCache cache;
    std::unique_ptr<EditorScene> scene;
};

TEST_F(EditorModel, LightEditMarksTheComponentChangedAndUndoRedoRestoreIt) {
    const ecs::Tick before = registry.changeTick<content::Light>(named("lamp"));
    registry.advanceTick();
    ASSERT_TRUE(setLumens("lamp", 1600.0f));
    EXPECT_EQ(lumens("lamp"), 1600.0f);
    // What LightTable's change query sees: the light changed after `before`.
    EXPECT_TRUE(registry.changedSince<content::Light>(named("lamp"), before));
    EXPECT_EQ(scene->commands().undoLabel(), "Set Light");
    ASSERT_TRUE(scene->undo());
    EXPECT_EQ(lumens("lamp"), 800.0f);
    EXPECT_FALSE(scene->undo());
    ASSERT_TRUE(scene->redo());
    EXPECT_EQ(lumens("lamp"), 1600.0f);
    EXPECT_FALSE(scene->redo());
}

TEST_F(EditorModel, ADragIsOneUndoStepAndANewEditClearsRedo) {
    for (float v : {900.0f, 1000.0f, 1100.0f})
        ASSERT_TRUE(setLumens("lamp", v, 42));
    EXPECT_EQ(scene->commands().undoCount(), 1u);
    scene->commands().closeMerge();  // the slider was released
    ASSERT_TRUE(setLumens("lamp", 2000.0f, 42));
    EXPECT_EQ(scene->commands().undoCount(), 2u);
    ASSERT_TRUE(scene->undo());
    EXPECT_EQ(lumens("lamp"), 1100.0f);
    ASSERT_TRUE(scene->undo());
    EXPECT_EQ(lumens("lamp"), 800.0f);
    ASSERT_TRUE(scene->redo());
    ASSERT_TRUE(setLumens("bulb", 5.0f));
    EXPECT_FALSE(scene->commands().canRedo());
    EXPECT_EQ(lumens("lamp"), 1100.0f);
}

TEST_F(EditorModel, RenameAndCreateUndoAndRedo) {
    ecs::Entity lamp = named("lamp");
    ASSERT_TRUE(scene->execute(setComponent(*scene, lamp, content::Name{"desk lamp"}, "Rename")));
    EXPECT_EQ(named("lamp"), ecs::kNullEntity);
    EXPECT_EQ(named("desk lamp"), lamp);

    auto create = std::make_unique<CreateEntityCommand>(*scene, lamp, "spot", content::Light{});
    const uint64_t id = create->createdId();
    ASSERT_TRUE(scene->execute(std::move(create)));
    ecs::Entity spot = scene->find(id);
    ASSERT_NE(spot, ecs::kNullEntity);
    EXPECT_EQ(ecs::parentOf(registry, spot), lamp);
    EXPECT_TRUE(registry.has<content::Light>(spot));
    ASSERT_TRUE(scene->undo());
    EXPECT_EQ(scene->find(id), ecs::kNullEntity);
    ASSERT_TRUE(scene->undo());
    EXPECT_EQ(named("lamp"), lamp);
    ASSERT_TRUE(scene->redo());
    ASSERT_TRUE(scene->redo());
    EXPECT_NE(scene->find(id), ecs::kNullEntity);
    EXPECT_EQ(ecs::parentOf(registry, scene->find(id)), lamp);
}

TEST_F(EditorModel, DuplicateCopiesTheSubtreeAndUndoRemovesIt) {
    const size_t entities = registry.aliveCount();
    uint64_t copyId = 0;
    ASSERT_TRUE(scene->execute(duplicateEntity(*scene, named("lamp"), &copyId)));
    EXPECT_EQ(registry.aliveCount(), entities + 2);
    ecs::Entity copy = scene->find(copyId);
    EXPECT_EQ(scene->displayName(copy), "lamp copy");
    std::vector<ecs::Entity> children = ecs::childrenOf(registry, copy);
    ASSERT_EQ(children.size(), 1u);
    EXPECT_EQ(scene->displayName(children[0]), "bulb");
    EXPECT_NE(children[0], named("bulb"));  // a copy, not the original moved
    EXPECT_EQ(registry.get<content::Light>(children[0]).sourceRadius, 0.1f);
    // Edits of the copy leave the original alone.
    ASSERT_TRUE(setLumens("lamp copy", 42.0f));
    EXPECT_EQ(lumens("lamp"), 800.0f);
    ASSERT_TRUE(scene->undo());
    ASSERT_TRUE(scene->undo());
    EXPECT_EQ(registry.aliveCount(), entities);
    EXPECT_EQ(scene->find(copyId), ecs::kNullEntity);
}

TEST_F(EditorModel, DeleteUndoRestoresComponentsLinksAndEarlierCommands) {
    ASSERT_TRUE(setLumens("lamp", 1234.0f));
    scene->select(named("bulb"));
    const uint64_t bulbId = scene->selectedId();
    ASSERT_TRUE(scene->execute(deleteEntity(*scene, named("lamp"))));
    EXPECT_EQ(named("lamp"), ecs::kNullEntity);
    EXPECT_EQ(named("bulb"), ecs::kNullEntity);  // descendants go too
    EXPECT_EQ(scene->selected(), ecs::kNullEntity);
    ASSERT_TRUE(scene->undo());
    ASSERT_NE(named("lamp"), ecs::kNullEntity);
    EXPECT_EQ(lumens("lamp"), 1234.0f);
    EXPECT_EQ(ecs::parentOf(registry, named("bulb")), named("lamp"));
    EXPECT_EQ(scene->find(bulbId), named("bulb"));
    // The light edit made before the delete still undoes on the recreated entity.
    ASSERT_TRUE(scene->undo());
    EXPECT_EQ(lumens("lamp"), 800.0f);
    ASSERT_TRUE(scene->redo());
    ASSERT_TRUE(scene->redo());
    EXPECT_EQ(named("lamp"), ecs::kNullEntity);
}

TEST_F(EditorModel, ReparentAndRefuseCycles) {
    ecs::Entity bulb = named("bulb");
    ecs::Entity lamp = named("lamp");
    ASSERT_TRUE(scene->execute(reparentEntity(*scene, bulb, ecs::kNullEntity)));
    EXPECT_EQ(ecs::parentOf(registry, bulb), ecs::kNullEntity);
    ASSERT_TRUE(scene->execute(reparentEntity(*scene, lamp, bulb)));
    EXPECT_EQ(ecs::parentOf(registry, lamp), bulb);
    // bulb under its own child: refused, nothing recorded.
    EXPECT_FALSE(scene->execute(reparentEntity(*scene, bulb, lamp)));
    EXPECT_FALSE(scene->execute(reparentEntity(*scene, bulb, bulb)));
    EXPECT_EQ(scene->commands().undoCount(), 2u);
    ASSERT_TRUE(scene->undo());
    ASSERT_TRUE(scene->undo());
    EXPECT_EQ(ecs::parentOf(registry, bulb), lamp);
    EXPECT_EQ(ecs::parentOf(registry, lamp), ecs::kNullEntity);
}

TEST_F(EditorModel, SaveWritesEditsHierarchyAndRebasedAssetPaths) {
    ASSERT_TRUE(setLumens("lamp", 1600.0f));
    ASSERT_TRUE(
        scene->execute(std::make_unique<CreateEntityCommand>(*scene, named("lamp"), "extra")));
    EXPECT_TRUE(scene->modified());
    const content::SceneDocument saved = saveAndLoad(dir / "saved" / "edited.scene.json");
    EXPECT_FALSE(scene->modified());
    ASSERT_EQ(saved.entities.size(), 5u);
    const content::SceneEntity* lamp = entityNamed(saved, "lamp");
    ASSERT_TRUE(lamp && lamp->light);
    EXPECT_EQ(lamp->light->lumens, 1600.0f);
    const content::SceneEntity* extra = entityNamed(saved, "extra");
    ASSERT_TRUE(extra);
    ASSERT_GE(extra->parent, 0);
    EXPECT_EQ(saved.entities[size_t(extra->parent)].name, "lamp");
    const content::SceneEntity* floor = entityNamed(saved, "floor");
    ASSERT_TRUE(floor && floor->mesh);
    // Still points at <dir>/models/floor.glb from the new directory.
    EXPECT_EQ(floor->mesh->gltfPath, "../models/floor.glb");
    // Scene order is kept: the loaded entities first, in file order.
    EXPECT_EQ(saved.entities[0].name, "floor");
    EXPECT_EQ(saved.entities[3].name, "camera");
    ASSERT_TRUE(scene->undo());
    EXPECT_TRUE(scene->modified());
}

// The scene-wide render settings are no entity's component: a save must not drop them (the
// "brdf" was dropped before). Every row of the settings table is written back, edited or not.
TEST_F(EditorModel, SaveKeepsTheScenesRenderSettings) {
    EXPECT_FALSE(saveAndLoad(dir / "saved" / "none.scene.json").settings.brdf.has_value());
    content::RenderSettingChoices settings;
    settings.brdf = content::BrdfModel::Ue4;
    settings.aa = content::AntiAliasing::Fxaa;
    settings.msaaSamples = 4u;
    settings.bloomStrength = 0.0f;
    settings.exposure = content::FrameExposure::Auto;
    settings.exposureCompensation = 0.5f;
    settings.scattering = content::ScatteringMode::Off;
    settings.volumetrics = content::VolumetricsMode::Reference;
    settings.skyOcclusion = content::SkyOcclusionMode::Off;
    settings.volumeProxies = true;
    settings.renderScale = 0.75f;
    scene->setSceneRenderSettings(settings);
    scene->setSceneQuality(content::QualityLevel::Low);
    EXPECT_FALSE(scene->modified());  // what the file held is no edit
    ASSERT_TRUE(setLumens("lamp", 900.0f));
    const content::SceneDocument doc = saveAndLoad(dir / "saved" / "settings.scene.json");
    EXPECT_EQ(doc.settings, settings);
    EXPECT_EQ(doc.quality, content::QualityLevel::Low);
    // An edit of a setting alone marks the scene modified until it is saved.
    settings.ssr = content::SsrMode::Hiz;
    scene->setSceneRenderSettings(settings, true);
    EXPECT_TRUE(scene->modified());
    EXPECT_EQ(saveAndLoad(dir / "saved" / "ssr.scene.json").settings.ssr, content::SsrMode::Hiz);
    EXPECT_FALSE(scene->modified());
}

// Issue 25: the scene-wide "ambient_occlusion" the inspector edits is saved, and an edit of
// it marks the scene modified until the save.
TEST_F(EditorModel, SaveKeepsTheScenesAmbientOcclusionSetting) {
    EXPECT_FALSE(saveAndLoad(dir / "saved" / "no_ao.scene.json").ambientOcclusion.has_value());
    EXPECT_FALSE(scene->modified());
    scene->setSceneAmbientOcclusion(content::SceneAmbientOcclusion{0.8f, 0.5f}, true);
    EXPECT_TRUE(scene->modified());
    const content::SceneDocument doc = saveAndLoad(dir / "saved" / "ao.scene.json");
    EXPECT_FALSE(scene->modified());
    ASSERT_TRUE(doc.ambientOcclusion.has_value());
    EXPECT_EQ(doc.ambientOcclusion->radius, 0.8f);
    EXPECT_EQ(doc.ambientOcclusion->intensity, 0.5f);
}

// Issue 41: the quality preset the inspector edits marks the scene modified and is saved;
// "device's" (unset) saves no key.
TEST_F(EditorModel, SaveKeepsTheQualityPresetEditedInTheInspector) {
    EXPECT_FALSE(saveAndLoad(dir / "saved" / "no_quality.scene.json").quality.has_value());
    scene->setSceneQuality(content::QualityLevel::Ultra, true);
    EXPECT_TRUE(scene->modified());
    EXPECT_EQ(saveAndLoad(dir / "saved" / "ultra.scene.json").quality,
              content::QualityLevel::Ultra);
    EXPECT_FALSE(scene->modified());
    scene->setSceneQuality(std::nullopt, true);
    EXPECT_FALSE(saveAndLoad(dir / "saved" / "device.scene.json").quality.has_value());
}

TEST_F(EditorModel, SavingIntoAMissingDirectoryFailsNamingTheFileAndKeepsModified) {
    ASSERT_TRUE(setLumens("lamp", 1600.0f));
    const fs::path bad = dir / "no_such_dir" / "x.scene.json";
    const std::string error = scene->save(bad);
    EXPECT_NE(error.find("x.scene.json"), std::string::npos) << error;
    EXPECT_TRUE(scene->modified());
    EXPECT_FALSE(fs::exists(bad));
}

TEST_F(EditorModel, PropertyEditsByNameAndTheirErrors) {
    std::string error;
    ASSERT_TRUE(
        scene->execute(propertyEdit(*scene, named("lamp"), "light.lumens", {1600.0f}, error)))
        << error;
    EXPECT_EQ(lumens("lamp"), 1600.0f);
    ASSERT_TRUE(scene->execute(
        propertyEdit(*scene, named("lamp"), "transform.position", {1.0f, 2.0f, 3.0f}, error)));
    EXPECT_EQ(registry.get<ecs::LocalTransform>(named("lamp")).position.y, 2.0f);
    ASSERT_TRUE(
        scene->execute(propertyEdit(*scene, named("camera"), "camera.aperture", {8.0f}, error)));
    EXPECT_EQ(registry.get<content::Camera>(named("camera")).aperture, 8.0f);

    EXPECT_FALSE(propertyEdit(*scene, named("lamp"), "light.lumen", {1.0f}, error));
    EXPECT_EQ(error, "light.lumen: unknown property");
    EXPECT_FALSE(propertyEdit(*scene, named("lamp"), "light.color", {1.0f}, error));
    EXPECT_EQ(error, "light.color: expects 3 value(s), got 1");
    EXPECT_FALSE(propertyEdit(*scene, named("camera"), "light.lumens", {1.0f}, error));
    EXPECT_EQ(error, "light.lumens: the entity has no light");
    EXPECT_FALSE(propertyEdit(*scene, named("floor"), "material.roughness", {0.5f}, error));
    EXPECT_EQ(error, "material.roughness: the entity has no loaded mesh");
    EXPECT_EQ(scene->commands().undoCount(), 3u);
}

// Issue 22: the editor accepted lumens -1, attenuation radius 0, source radius -2 and field of
// view -1 and saved them; the loader then dropped the light, and the next save lost it for
// good. The editor now applies the loader's rules: refused, or clamped with a notice.
TEST_F(EditorModel, EditsTheLoaderWouldRejectAreRefusedAndAbsurdOnesClamped) {
    std::string error;
    const std::pair<const char*, float> refused[] = {{"light.lumens", -1.0f},
                                                     {"light.attenuationRadius", 0.0f},
                                                     {"light.sourceRadius", -2.0f},
                                                     {"camera.verticalFov", -1.0f},
                                                     {"camera.verticalFov", 3.1415927f}};
    for (const auto& [property, value] : refused) {
        const char* entity = std::string(property).starts_with("camera") ? "camera" : "lamp";
        EXPECT_FALSE(propertyEdit(*scene, named(entity), property, {value}, error)) << property;
        EXPECT_NE(error.find(property), std::string::npos) << error;
    }
    EXPECT_NE(error.find("between 0 and pi"), std::string::npos) << error;
    EXPECT_FALSE(
        propertyEdit(*scene, named("lamp"), "transform.rotation", {0.0f, 0.0f, 0.0f, 0.0f}, error));
    EXPECT_NE(error.find("zero quaternion"), std::string::npos) << error;
    EXPECT_EQ(scene->commands().undoCount(), 0u);

    std::string notice;
    ASSERT_TRUE(scene->execute(
        propertyEdit(*scene, named("lamp"), "light.lumens", {3e38f}, error, &notice)))
        << error;
    EXPECT_EQ(lumens("lamp"), content::kMaxLumens);
    EXPECT_NE(notice.find("beyond the limit"), std::string::npos) << notice;

    // What the editor saves, the loader keeps, without a message.
    const fs::path path = dir / "saved" / "checked.scene.json";
    ASSERT_EQ(scene->save(path), "");
    content::Diagnostics diagnostics;
    std::optional<content::SceneDocument> doc = content::loadSceneFile(path, diagnostics);
    ASSERT_TRUE(doc);
    EXPECT_FALSE(diagnostics.mentions("/light")) << diagnostics.toString();
    ASSERT_TRUE(doc->entities[1].light);
    EXPECT_EQ(doc->entities[1].light->lumens, content::kMaxLumens);
}

// Issue 21: a material's layers and mask edit as one undoable material edit each, and the
// scene's layer library and the layered override survive the editor's save.
TEST_F(EditorModel, MaterialLayerEditsUndoAndSaveWithTheLibrary) {
    content::Model model;
    content::Mesh& mesh = model.meshes.emplace_back();
    mesh.primitives.push_back(content::makeSphere(1, 8, 4));
    ecs::Entity floor = named("floor");
    registry.get<content::MeshInstance>(floor).model = &model;
    registry.get<content::MeshInstance>(floor).mesh = 0;
    content::MaterialLayer paint, rust;
    paint.name = "paint";
    paint.metallicFactor = 1.0f;
    rust.name = "rust";
    rust.roughnessFactor = 0.9f;
    scene->setSceneMaterialLayers({paint, rust});

    content::Material m = effectiveMaterial(*scene, floor, 0);
    m.layering.layers = {paint, rust};  // what the inspector's "Add layer" does, twice
    m.layering.maskSource = content::LayerMaskSource::VertexColor;
    ASSERT_TRUE(scene->execute(setMaterial(*scene, floor, 0, m)));
    m.layering.layers[1].roughnessFactor = 0.6f;  // the inspector's layer slider
    m.layering.layers[1].uvScale = {4.0f, 4.0f};
    ASSERT_TRUE(scene->execute(setMaterial(*scene, floor, 0, m)));
    EXPECT_EQ(effectiveMaterial(*scene, floor, 0).layering.layers[1].roughnessFactor, 0.6f);
    EXPECT_EQ(scene->sceneMaterialLayers()[1].roughnessFactor, 0.9f);  // the library's stays

    const fs::path path = dir / "saved" / "layered.scene.json";
    ASSERT_EQ(scene->save(path), "");
    content::Diagnostics diagnostics;
    std::optional<content::SceneDocument> doc = content::loadSceneFile(path, diagnostics);
    ASSERT_TRUE(doc);
    EXPECT_FALSE(diagnostics.hasErrors()) << diagnostics.toString();
    ASSERT_EQ(doc->materialLayers.size(), 2u);
    EXPECT_EQ(doc->materialLayers[1].roughnessFactor, 0.9f);
    const content::SceneEntity& saved = doc->entities[size_t(
        std::find_if(doc->entities.begin(), doc->entities.end(),
                     [](const content::SceneEntity& e) { return e.name == "floor"; }) -
        doc->entities.begin())];
    ASSERT_EQ(saved.materialOverrides.size(), 1u);
    const content::MaterialLayering& layering = saved.materialOverrides[0].material.layering;
    ASSERT_EQ(layering.layers.size(), 2u);
    EXPECT_EQ(layering.layers[1].roughnessFactor, 0.6f);
    EXPECT_EQ(layering.layers[1].uvScale[0], 4.0f);
    EXPECT_EQ(layering.maskSource, content::LayerMaskSource::VertexColor);

    ASSERT_TRUE(scene->undo());
    EXPECT_EQ(effectiveMaterial(*scene, floor, 0).layering.layers[1].roughnessFactor, 0.9f);
    ASSERT_TRUE(scene->undo());
    EXPECT_FALSE(effectiveMaterial(*scene, floor, 0).layered());
}

TEST_F(EditorModel, AddAndRemoveComponentsUndo) {
    ecs::Entity camera = named("camera");
    ASSERT_TRUE(scene->execute(setComponent(*scene, camera, content::Light{}, "Add Light")));
    EXPECT_TRUE(registry.has<content::Light>(camera));
    ASSERT_TRUE(scene->undo());
    EXPECT_FALSE(registry.has<content::Light>(camera));
    ASSERT_TRUE(scene->execute(removeComponent<content::Light>(*scene, named("lamp"), "Remove")));
    EXPECT_FALSE(registry.has<content::Light>(named("lamp")));
    EXPECT_FALSE(removeComponent<content::Light>(*scene, named("lamp"), "Remove"));
    ASSERT_TRUE(scene->undo());
    EXPECT_EQ(lumens("lamp"), 800.0f);
}

TEST_F(EditorModel, MaterialEditsWriteOverridesAndKeepTheModelMaterial) {
    content::Model model;
    content::Material red;
    red.baseColorFactor = {1, 0, 0, 1};
    red.roughnessFactor = 0.8f;
    model.materials.push_back(red);
    content::Mesh& mesh = model.meshes.emplace_back();
    mesh.primitives.push_back(content::makeBox({1, 1, 1}));
    mesh.primitives.back().material = 0;
    mesh.primitives.push_back(content::makeSphere(1, 8, 4));  // the glTF default material
    ecs::Entity floor = named("floor");
    registry.get<content::MeshInstance>(floor).model = &model;
    registry.get<content::MeshInstance>(floor).mesh = 0;

    ASSERT_EQ(primitiveCount(*scene, floor), 2u);
    EXPECT_EQ(effectiveMaterial(*scene, floor, 0).roughnessFactor, 0.8f);
    EXPECT_EQ(effectiveMaterial(*scene, floor, 1).roughnessFactor, 1.0f);
    std::string error;
    const ecs::Tick before = registry.currentTick();
    registry.advanceTick();
    ASSERT_TRUE(scene->execute(propertyEdit(*scene, floor, "material.roughness", {0.25f}, error)));
    // Frame extraction remakes override materials when this tick moves.
    EXPECT_TRUE(registry.changedSince<content::MaterialOverrides>(floor, before));
    EXPECT_EQ(effectiveMaterial(*scene, floor, 0).roughnessFactor, 0.25f);
    EXPECT_EQ(effectiveMaterial(*scene, floor, 0).baseColorFactor[1], 0.0f);  // rest kept
    EXPECT_EQ(model.materials[0].roughnessFactor, 0.8f);  // the shared model is untouched
    content::Material legacy = effectiveMaterial(*scene, floor, 1);
    legacy.shadingModel = content::ShadingModel::Legacy;
    ASSERT_TRUE(scene->execute(setMaterial(*scene, floor, 1, legacy)));
    EXPECT_EQ(registry.get<content::MaterialOverrides>(floor).overrides.size(), 2u);
    EXPECT_FALSE(setMaterial(*scene, floor, 2, legacy));
    ASSERT_TRUE(scene->undo());
    ASSERT_TRUE(scene->undo());
    EXPECT_FALSE(registry.has<content::MaterialOverrides>(floor));
    EXPECT_EQ(effectiveMaterial(*scene, floor, 0).roughnessFactor, 0.8f);

    // Issue 21: the material extensions edit and undo like any other field.
    ASSERT_TRUE(scene->execute(propertyEdit(*scene, floor, "material.anisotropy", {0.7f}, error)));
    ASSERT_TRUE(scene->execute(propertyEdit(*scene, floor, "material.clearcoat", {1.0f}, error)));
    ASSERT_TRUE(
        scene->execute(propertyEdit(*scene, floor, "material.clearcoatRoughness", {0.1f}, error)));
    EXPECT_EQ(effectiveMaterial(*scene, floor, 0).anisotropyStrength, 0.7f);
    EXPECT_EQ(effectiveMaterial(*scene, floor, 0).clearcoatFactor, 1.0f);
    EXPECT_EQ(effectiveMaterial(*scene, floor, 0).clearcoatRoughnessFactor, 0.1f);
    ASSERT_TRUE(scene->undo());
    EXPECT_EQ(effectiveMaterial(*scene, floor, 0).clearcoatRoughnessFactor, 0.0f);
    ASSERT_TRUE(scene->undo());
    EXPECT_FALSE(effectiveMaterial(*scene, floor, 0).clearCoated());
    ASSERT_TRUE(scene->undo());
    EXPECT_FALSE(effectiveMaterial(*scene, floor, 0).anisotropic());

    // Issue 25: Cavity edits like any other field and is clamped to [0, 1].
    ASSERT_TRUE(scene->execute(propertyEdit(*scene, floor, "material.cavity", {0.4f}, error)));
    EXPECT_EQ(effectiveMaterial(*scene, floor, 0).cavity, 0.4f);
    ASSERT_TRUE(scene->execute(propertyEdit(*scene, floor, "material.cavity", {3.0f}, error)));
    EXPECT_EQ(effectiveMaterial(*scene, floor, 0).cavity, 1.0f);
    // Issue 44: the clamp says so, as every other clamped edit does (3e38 was silent).
    std::string notice;
    ASSERT_TRUE(
        scene->execute(propertyEdit(*scene, floor, "material.cavity", {3e38f}, error, &notice)));
    EXPECT_EQ(effectiveMaterial(*scene, floor, 0).cavity, 1.0f);
    EXPECT_NE(notice.find("cavity"), std::string::npos) << notice;
    EXPECT_NE(notice.find("clamped to 1"), std::string::npos) << notice;
    ASSERT_TRUE(scene->execute(
        propertyEdit(*scene, floor, "material.anisotropy", {-5.0f}, error, &notice)));
    EXPECT_EQ(effectiveMaterial(*scene, floor, 0).anisotropyStrength, 0.0f);
    EXPECT_NE(notice.find("anisotropyStrength"), std::string::npos) << notice;
    EXPECT_FALSE(propertyEdit(*scene, floor, "material.clearcoat", {std::nanf("")}, error));
    EXPECT_NE(error.find("clearcoatFactor"), std::string::npos) << error;
    ASSERT_TRUE(scene->undo());
    ASSERT_TRUE(scene->undo());
    ASSERT_TRUE(scene->undo());
    ASSERT_TRUE(scene->undo());
    EXPECT_EQ(effectiveMaterial(*scene, floor, 0).cavity, 1.0f);
}

}  // namespace
}  // namespace candela::editor

namespace candela::editor {
namespace {

// Issue 46: the inspector's physics sections edit RigidBody and Collider through the loader's
// rules, deleting and undoing keeps them, and the save writes them as the scene file spells them.
TEST_F(EditorModel, RigidBodyAndColliderEditsFollowTheLoadersRulesAndSave) {
    const ecs::Entity lamp = named("lamp");
    content::Collider sphere;
    sphere.shape = content::ColliderShape::Sphere;
    sphere.radius = 0.0f;
    EXPECT_FALSE(checkEdit(sphere).accepted) << "a collider of no size";
    sphere.radius = 0.25f;
    content::RigidBody body;
    body.mass = -2.0f;
    const EditCheck clamped = checkEdit(body);
    EXPECT_TRUE(clamped.accepted);
    EXPECT_EQ(body.mass, 1.0f);
    EXPECT_NE(clamped.notice.find("mass"), std::string::npos) << clamped.notice;
    ASSERT_TRUE(scene->execute(setComponent(*scene, lamp, sphere, "Add Collider")));
    ASSERT_TRUE(scene->execute(setComponent(*scene, lamp, body, "Add Rigid Body")));

    // Deleting the lamp and undoing brings both back (the editor's entity snapshots).
    ASSERT_TRUE(scene->execute(deleteEntity(*scene, lamp)));
    ASSERT_TRUE(scene->undo());
    const ecs::Entity restored = named("lamp");
    ASSERT_TRUE(registry.has<content::Collider>(restored));
    EXPECT_EQ(registry.get<content::Collider>(restored), sphere);
    EXPECT_EQ(registry.get<content::RigidBody>(restored), body);

    const content::SceneDocument saved = saveAndLoad(dir / "saved" / "bodies.scene.json");
    const content::SceneEntity* entity = entityNamed(saved, "lamp");
    ASSERT_TRUE(entity && entity->collider && entity->rigidBody);
    EXPECT_EQ(*entity->collider, sphere);
    EXPECT_EQ(*entity->rigidBody, body);
}

}  // namespace
}  // namespace candela::editor

namespace candela::editor {
namespace {

// Issue 47: the inspector's audio sections edit AudioSource and AudioListener through the
// loader's rules; deleting and undoing keeps them, and the save writes the clip relative to the
// saved scene file.
TEST_F(EditorModel, AudioEditsFollowTheLoadersRulesAndSaveTheClipRelative) {
    const ecs::Entity lamp = named("lamp");
    content::AudioSource sound;
    EXPECT_FALSE(checkEdit(sound).accepted) << "a source without a clip";
    sound.clip = (dir / "sounds" / "hum.wav").string();
    sound.gain = -1.0f;
    const EditCheck clamped = checkEdit(sound);
    EXPECT_TRUE(clamped.accepted);
    EXPECT_EQ(sound.gain, 0.0f);
    EXPECT_NE(clamped.notice.find("gain"), std::string::npos) << clamped.notice;
    sound.gain = 0.5f;
    sound.loop = true;
    ASSERT_TRUE(scene->execute(setComponent(*scene, lamp, sound, "Add Audio Source")));
    ASSERT_TRUE(
        scene->execute(setComponent(*scene, lamp, content::AudioListener{}, "Add Listener")));

    ASSERT_TRUE(scene->execute(deleteEntity(*scene, lamp)));
    ASSERT_TRUE(scene->undo());
    const ecs::Entity restored = named("lamp");
    ASSERT_TRUE(registry.has<content::AudioSource>(restored));
    EXPECT_EQ(registry.get<content::AudioSource>(restored), sound);
    EXPECT_TRUE(registry.has<content::AudioListener>(restored));

    const content::SceneDocument saved = saveAndLoad(dir / "saved" / "sounds.scene.json");
    const content::SceneEntity* entity = entityNamed(saved, "lamp");
    ASSERT_TRUE(entity && entity->audioSource && entity->audioListener);
    EXPECT_EQ(entity->audioSource->clip, "../sounds/hum.wav");
    EXPECT_EQ(entity->audioSource->gain, 0.5f);
    EXPECT_TRUE(entity->audioSource->loop);
}

}  // namespace
}  // namespace candela::editor
