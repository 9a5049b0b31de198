#pragma once
// Collider component: the shape an entity collides with (physics/README.md).
//
//   "collider": {"shape": "box"}                     fits the builtin unit box
//   "collider": {"shape": "sphere", "radius": 0.25}  explicit size, metres in local units
//   "collider": {"shape": "box", "trigger": true}    overlap events only, no contact response
//
// Sizes are in the entity's local units and scale with its world transform. A shape without
// an explicit size fits the builtin mesh of its name (builtin_meshes.h): the unit box (half
// extents 0.5), the sphere of diameter 1; along local +Y, a capsule of radius 0.5 and height 2
// (a standing figure's proportions) and a cylinder of radius 0.5 and height 1. A convex hull or
// triangle mesh takes its points from the entity's MeshInstance. A Collider on an entity without a
// RigidBody, below an ancestor that has one, is part of the ancestor's body (a compound shape).
#include <cstdint>
#include <optional>

#include "candela/ecs/transform_math.h"

namespace candela::content {

enum class ColliderShape : std::uint8_t {
    Sphere,
    Box,
    Capsule,
    Cylinder,
    ConvexHull,
    TriangleMesh
};

// Collision layers are bits: two colliders touch when each one's layer is in the other's mask.
inline constexpr std::uint32_t kDefaultCollisionLayer = 1u;
inline constexpr std::uint32_t kAllCollisionLayers = 0xffffffffu;

struct Collider {
    ColliderShape shape = ColliderShape::Box;
    std::optional<float> radius;           // sphere, capsule, cylinder
    std::optional<ecs::Vec3> halfExtents;  // box
    std::optional<float> height;           // capsule, cylinder: end to end along +Y
    bool trigger = false;                  // reports overlaps; nothing bumps into it
    std::uint32_t layer = kDefaultCollisionLayer;
    std::uint32_t mask = kAllCollisionLayers;

    bool operator==(const Collider&) const = default;
};

// The sizes a collider has before the entity's scale: explicit ones, else the builtin mesh's.
inline constexpr float kDefaultColliderRadius = 0.5f;
inline constexpr float kDefaultCapsuleHeight = 2.0f;
inline constexpr float kDefaultCylinderHeight = 1.0f;
inline constexpr ecs::Vec3 kDefaultColliderHalfExtents{0.5f, 0.5f, 0.5f};

}  // namespace candela::content
