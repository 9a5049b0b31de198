#pragma once
// Turning loaded content into entities, and entities back into a scene file.
//
//   ecs::Registry registry;
//   auto nodes = instantiateModel(registry, model, "models/DamagedHelmet.glb");
//   auto entities = instantiateScene(registry, sceneDocument);
//   ecs::propagateTransforms(registry);            // fills WorldTransform
//   SceneDocument saved = captureScene(registry);  // every SceneMember entity, in order
//
// Entities get Name, ecs::LocalTransform, ecs::WorldTransform and ecs hierarchy links, plus
// MeshInstance, MaterialOverrides, Light, Camera, Sky, GameData as the source has them.
#include <string>
#include <vector>

#include <candela/ecs/entity.h>
#include <candela/ecs/registry.h>

#include "candela/content/model.h"
#include "candela/content/scene_file.h"

namespace candela::content {

// One entity per node reachable from model.rootNodes, parented as in the file and the roots
// under `parent` (kNullEntity: top level). `gltfPath` is what MeshInstance components will
// name. Returns node index -> entity (kNullEntity for nodes outside the scene).
std::vector<ecs::Entity> instantiateModel(ecs::Registry& registry, const Model& model,
                                          const std::string& gltfPath,
                                          ecs::Entity parent = ecs::kNullEntity);

// One entity per SceneEntity, in order, each tagged SceneMember{index}. Returns them in order.
std::vector<ecs::Entity> instantiateScene(ecs::Registry& registry, const SceneDocument& scene);

// Every entity with SceneMember, sorted by SceneMember::order (ties by entity), as a scene
// document; parents outside that set make the entity a root.
SceneDocument captureScene(ecs::Registry& registry);

}  // namespace candela::content
