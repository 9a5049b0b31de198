#include "lit_scene_file.h"

#include <cmath>
#include <fstream>
#include <numbers>

#include "candela/content/scene_file.h"

namespace candela::golden::test {

namespace {

using namespace candela::content;

SceneEntity meshEntity(const std::string& name, const std::string& gltf, int mesh) {
    SceneEntity entity;
    entity.name = name;
    entity.mesh = MeshReference{gltf, mesh};
    return entity;
}

Material sphereMaterial(const LitScene& scene) {
    Material material;
    material.name = "sphere";
    if (scene.sphereShadingModel == "legacy") material.shadingModel = ShadingModel::Legacy;
    if (scene.sphereShadingModel == "subsurface") material.shadingModel = ShadingModel::Subsurface;
    if (scene.sphereShadingModel == "unlit") material.shadingModel = ShadingModel::Unlit;
    material.baseColorFactor = {scene.sphereBaseColor[0], scene.sphereBaseColor[1],
                                scene.sphereBaseColor[2], 1.0f};
    material.metallicFactor = scene.sphereMetallic;
    material.roughnessFactor = scene.sphereRoughness;
    material.diffuseColor = scene.sphereBaseColor;
    material.specularColor = {0.04f, 0.04f, 0.04f};
    return material;
}

}  // namespace

std::filesystem::path writeLitSceneFile(const LitScene& scene, const std::filesystem::path& dir,
                                        const std::string& name, std::string& error) {
    const std::string gltf = name + ".gltf";
    std::ofstream(dir / gltf) << litSceneGltf(scene);

    SceneDocument document;
    SceneEntity sphere = meshEntity("sphere", gltf, 0);
    sphere.transform.translation = {0.0f, 0.5f, 0.0f};
    sphere.materialOverrides.push_back({0, sphereMaterial(scene)});
    document.entities.push_back(sphere);
    document.entities.push_back(meshEntity("floor", gltf, 1));

    SceneEntity light;
    light.name = "light";
    light.transform.translation = scene.lightPosition;
    light.light = Light{};
    light.light->lumens = float(4 * std::numbers::pi * scene.lightCandela);
    light.light->attenuationRadius = scene.lightRange;
    document.entities.push_back(light);

    SceneEntity camera;
    camera.name = "camera";
    const double pitch = -std::atan2(0.5, 2.6);  // as in the glTF: looking at the sphere
    camera.transform.translation = {0.0f, 1.0f, 2.6f};
    camera.transform.rotation = {float(std::sin(pitch / 2)), 0.0f, 0.0f,
                                 float(std::cos(pitch / 2))};
    camera.camera = Camera{};
    camera.camera->verticalFov = 0.7f;
    document.entities.push_back(camera);

    const std::filesystem::path path = dir / (name + ".scene.json");
    error = saveSceneFile(path, document);
    return error.empty() ? path : std::filesystem::path();
}

}  // namespace candela::golden::test
