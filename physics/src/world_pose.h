#pragma once
// Where an entity is in the world, split into what a rigid body takes (position, rotation) and
// what its collider's size takes (scale).
#include <optional>

#include "candela/ecs/registry.h"
#include "candela/ecs/transform_math.h"

namespace candela::physics {

struct WorldPose {
    ecs::Vec3 position{};
    ecs::Quat rotation{};
    ecs::Vec3 scale{1.0f, 1.0f, 1.0f};
};

// Translation, rotation and per-axis scale of an affine matrix (shear, which only a
// non-uniformly scaled parent of a rotated child has, is dropped).
WorldPose decompose(const ecs::Mat4& m);

// `entity`'s pose relative to its ancestor `owner`, from the LocalTransforms in between (which,
// unlike world transforms, do not change as the owner moves). Nullopt when a link has none.
std::optional<WorldPose> poseRelativeTo(const ecs::Registry& registry, ecs::Entity entity,
                                        ecs::Entity owner);

// A root entity's pose comes from its LocalTransform (what game code wrote this frame); a
// child's from its parent's WorldTransform and its own LocalTransform. Nullopt when the
// entity has no transform at all.
std::optional<WorldPose> worldPoseOf(const ecs::Registry& registry, ecs::Entity entity);

// The LocalTransform position and rotation that put `entity` at `world` (its parent's world
// transform undone; scale stays the entity's own).
void worldToLocal(const ecs::Registry& registry, ecs::Entity entity, ecs::Vec3 worldPosition,
                  ecs::Quat worldRotation, ecs::Vec3& localPosition, ecs::Quat& localRotation);

}  // namespace candela::physics
