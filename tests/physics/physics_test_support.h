#pragma once
// Bodies for physics tests: an entity with a transform, a collider and (optionally) a body.
#include <optional>

#include "candela/content/components/collider.h"
#include "candela/content/components/rigid_body.h"
#include "candela/ecs/registry.h"
#include "candela/ecs/transform.h"

namespace candela::physics::test {

inline ecs::Entity addCollider(ecs::Registry& registry, ecs::Vec3 position,
                               content::Collider collider,
                               std::optional<content::RigidBody> body = std::nullopt,
                               ecs::Quat rotation = {}, ecs::Vec3 scale = {1, 1, 1}) {
    const ecs::Entity e = registry.create();
    registry.emplace<ecs::LocalTransform>(e, ecs::LocalTransform{position, rotation, scale});
    registry.emplace<content::Collider>(e, collider);
    if (body) registry.emplace<content::RigidBody>(e, *body);
    return e;
}

inline content::Collider shapeOf(content::ColliderShape shape) {
    content::Collider collider;
    collider.shape = shape;
    return collider;
}

inline content::RigidBody dynamicBody(float mass = 1.0f) {
    content::RigidBody body;
    body.mass = mass;
    return body;
}

// A static floor: a 100 x 1 x 100 box whose top is at y = 0.
inline ecs::Entity addFloor(ecs::Registry& registry) {
    content::Collider floor = shapeOf(content::ColliderShape::Box);
    floor.halfExtents = ecs::Vec3{50, 0.5f, 50};
    return addCollider(registry, {0, -0.5f, 0}, floor);
}

inline ecs::Vec3 positionOf(const ecs::Registry& registry, ecs::Entity e) {
    return registry.get<ecs::LocalTransform>(e).position;
}

}  // namespace candela::physics::test
