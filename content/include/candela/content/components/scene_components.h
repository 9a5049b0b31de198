#pragma once
// Components the content module puts on entities besides Light, Camera and Sky.
#include <cstdint>
#include <string>
#include <vector>

#include "candela/content/material.h"

namespace candela::content {

struct Name {
    std::string value;
};

// Draw mesh `meshIndex` of the glTF at `gltfPath` (relative to the scene file; the asset cache
// resolves and loads it once however many entities use it).
struct MeshInstance {
    std::string gltfPath;
    std::int32_t meshIndex = 0;
};

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

// Marks an entity that belongs to the saved scene; `order` keeps file order across a
// load/save round trip.
struct SceneMember {
    std::uint32_t order = 0;
};

}  // namespace candela::content
