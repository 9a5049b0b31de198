#pragma once
// Scene-file components besides Name, MeshInstance, Light, Camera and Sky.
#include <cstdint>
#include <string>
#include <vector>

#include "candela/content/material.h"

namespace candela::content {

struct MaterialOverride {
    std::uint32_t primitive = 0;  // which primitive of the mesh
    Material material;            // texture indices refer to the same glTF's textures
};

struct MaterialOverrides {
    std::vector<MaterialOverride> overrides;
};

// Free-form game data, canonical JSON text (see SceneEntity::gameDataJson).
struct GameData {
    std::string json;
};

// A whole glTF model instantiated under the entity (SceneEntity::model); the entity also holds
// the model's AnimationPlayer when it has clips.
struct ModelInstance {
    std::string gltfPath;  // as the scene file stores it
};

// Marks an entity that belongs to the saved scene; `order` keeps file order across a
// load/save round trip.
struct SceneMember {
    std::uint32_t order = 0;
};

}  // namespace candela::content
