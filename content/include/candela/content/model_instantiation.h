#pragma once
// Turns a loaded glTF Model into entities: one per node of the shown scene, with Name,
// LocalTransform/WorldTransform, the glTF hierarchy (ecs::setParent) and, where the node has
// them, MeshInstance, Light and Camera components.
//
//   std::vector<ecs::Entity> entities = instantiateModel(registry, model);
//   ecs::propagateTransforms(registry);
//
// The model must outlive the entities (MeshInstance points at it).
#include <string>
#include <vector>

#include "candela/content/model.h"
#include "candela/ecs/entity.h"

namespace candela::ecs {
class Registry;
}

namespace candela::content {

// Returns the created entities, parents before children; `parent` (optional) becomes the
// parent of the model's root nodes. `gltfPath` is stored in each MeshInstance so the entities
// can be saved to a scene file.
std::vector<ecs::Entity> instantiateModel(ecs::Registry& registry, const Model& model,
                                          ecs::Entity parent = ecs::kNullEntity,
                                          const std::string& gltfPath = {});

}  // namespace candela::content
