#pragma once
// Bullet collision shapes made from a Collider at an entity's world scale.
#include <btBulletCollisionCommon.h>

#include <memory>
#include <string>
#include <vector>

#include "candela/content/components/collider.h"
#include "candela/content/model.h"
#include "candela/ecs/transform_math.h"

namespace candela::physics {

// A shape and what it points into (a triangle mesh's vertices, a compound's children), freed
// together.
struct ShapeData {
    std::unique_ptr<btTriangleMesh> triangles;
    std::unique_ptr<btCollisionShape> shape;
    std::vector<ShapeData> children;
};

// The shape's size in metres once `scale` is applied: sizes that are zero, negative or not
// finite give no shape and `problem` says which field. Hulls and meshes take their points from
// `mesh` (the entity's MeshInstance mesh, null when it has none); `dynamic` bodies get a hull
// where a triangle mesh was asked for (Bullet moves only convex shapes and compounds of them).
ShapeData makeColliderShape(const content::Collider& collider, ecs::Vec3 scale,
                            const content::Mesh* mesh, bool dynamic, std::string& problem);

}  // namespace candela::physics
