#pragma once
// MeshInstance component: draws one mesh of a loaded model at the entity's WorldTransform.
#include <cstdint>

namespace candela::content {

struct Model;

struct MeshInstance {
    const Model* model = nullptr;  // owned by whoever loaded it (asset cache, runtime scene)
    std::int32_t mesh = -1;        // into Model::meshes
};

}  // namespace candela::content
