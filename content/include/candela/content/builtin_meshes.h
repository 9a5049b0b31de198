#pragma once
// Meshes a scene file (or game code) can use without a glTF: a unit plane, box and sphere,
// each one primitive with a plain grey material (a scene's materialOverrides, or the mesh's
// own "material", changes it). Scale the entity to size them:
//
//   { "transform": {"scale": [20, 1, 20]}, "mesh": {"builtin": "plane",
//     "material": {"baseColorFactor": [0.3, 0.3, 0.35, 1], "metallicFactor": 0}} }
#include <cstdint>
#include <optional>
#include <string_view>

#include "candela/content/model.h"

namespace candela::content {

enum class BuiltinMesh : std::int32_t {
    Plane = 0,   // 1 x 1 in XZ, facing +Y
    Box = 1,     // 1 x 1 x 1
    Sphere = 2,  // diameter 1
};

// The spellings scene files use: "plane", "box", "sphere".
std::string_view builtinMeshName(BuiltinMesh mesh);
std::optional<BuiltinMesh> builtinMeshFromName(std::string_view name);
// "plane, box, sphere", for error messages.
std::string_view builtinMeshNames();

// One model holding the three meshes (index = the enum's value), built on first use and
// alive for the whole process, so MeshInstances may point at it freely.
const Model& builtinMeshModel();

}  // namespace candela::content
