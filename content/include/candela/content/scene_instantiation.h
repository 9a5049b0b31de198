#pragma once
// Scene files into entities, and entities back into a scene file. (glTF models alone:
// model_instantiation.h.)
//
//   AssetCache cache;
//   ecs::Registry registry;
//   auto entities = instantiateScene(registry, scene, "levels/one.scene.json", cache, diagnostics);
//   ecs::propagateTransforms(registry);            // fills WorldTransform
//   SceneDocument saved = captureScene(registry);  // every SceneMember entity, in order
//
// Entities get Name, ecs::LocalTransform, ecs::WorldTransform, ecs hierarchy links and
// SceneMember, plus MeshInstance, MaterialOverrides, Light, Camera, Sky, GameData as the
// scene entity has them.
#include <filesystem>
#include <vector>

#include <candela/ecs/entity.h>
#include <candela/ecs/registry.h>

#include "candela/content/asset_cache.h"
#include "candela/content/diagnostics.h"
#include "candela/content/scene_file.h"

namespace candela::content {

// One entity per SceneEntity, in order, each tagged SceneMember{index}; returns them in order.
// Mesh references load through `cache`, resolved against `sceneFile`'s directory; a glTF that
// fails to load (messages in `diagnostics`) or a mesh index it lacks leaves
// MeshInstance::model null but keeps the reference, so saving again loses nothing.
std::vector<ecs::Entity> instantiateScene(ecs::Registry& registry, const SceneDocument& scene,
                                          const std::filesystem::path& sceneFile, AssetCache& cache,
                                          Diagnostics& diagnostics);

// Every entity with SceneMember, sorted by SceneMember::order (ties by entity), as a scene
// document; parents outside that set make the entity a root.
SceneDocument captureScene(ecs::Registry& registry);

}  // namespace candela::content
