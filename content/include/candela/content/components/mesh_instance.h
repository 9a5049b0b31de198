#pragma once
// MeshInstance component: draws one mesh of a loaded model at the entity's WorldTransform.
#include <cstdint>
#include <string>

namespace candela::content {

struct Model;

struct MeshInstance {
    const Model* model = nullptr;  // owned by whoever loaded it (asset cache, runtime scene);
                                   // null when the referenced file failed to load
    std::int32_t mesh = -1;        // into Model::meshes
    // The glTF as a scene file names it (relative to the scene file); what captureScene()
    // writes back. Empty for models instantiated without a file reference.
    std::string gltfPath;
};

}  // namespace candela::content
