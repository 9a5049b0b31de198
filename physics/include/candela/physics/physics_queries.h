#pragma once
// Questions any system may ask of the physics world: what a ray hits, where a moving shape
// would first touch something, what overlaps a shape. They see the bodies as of the world's
// last step (or sync), and change nothing.
//
//   if (auto hit = raycast(physics, eye, forward, 100.0f)) aimAt(hit->entity, hit->point);
//   for (ecs::Entity e : overlap(physics, sphereOf(2.0f), blast)) damage(e);
#include <optional>
#include <vector>

#include "candela/content/components/collider.h"
#include "candela/ecs/entity.h"
#include "candela/ecs/transform_math.h"
#include "candela/physics/physics_world.h"

namespace candela::physics {

struct QueryFilter {
    // Colliders whose layer is in this mask are seen.
    std::uint32_t layers = content::kAllCollisionLayers;
    ecs::Entity ignore = ecs::kNullEntity;  // e.g. the body casting the ray
    bool triggers = false;                  // whether triggers are seen
};

struct Hit {
    // The collider's entity (a raycast names a compound body's part; a sweep names the body).
    ecs::Entity entity = ecs::kNullEntity;
    ecs::Vec3 point{};   // world space, on the surface hit
    ecs::Vec3 normal{};  // world space, unit, facing the ray or the moving shape
    float distance = 0;  // metres along the ray or sweep from its start
};

// The nearest hit of the ray from `origin` along `direction` (need not be unit) within
// `maxDistance` metres. Primitive shapes (sphere, box, capsule, cylinder) are hit exactly;
// hulls and triangle meshes as Bullet finds them.
std::optional<Hit> raycast(const PhysicsWorld& world, ecs::Vec3 origin, ecs::Vec3 direction,
                           float maxDistance, const QueryFilter& filter = {});
// Every collider the ray passes into, nearest first (one hit per entity).
std::vector<Hit> raycastAll(const PhysicsWorld& world, ecs::Vec3 origin, ecs::Vec3 direction,
                            float maxDistance, const QueryFilter& filter = {});

// The shape (a sphere, box, capsule or cylinder Collider, sizes in metres) moved without
// turning from `from` to `to`: the first thing it would touch, `distance` how far it got.
std::optional<Hit> sweep(const PhysicsWorld& world, const content::Collider& shape,
                         ecs::Quat rotation, ecs::Vec3 from, ecs::Vec3 to,
                         const QueryFilter& filter = {});

// Every entity whose collider overlaps the shape placed at `position`, in creation order.
std::vector<ecs::Entity> overlap(const PhysicsWorld& world, const content::Collider& shape,
                                 ecs::Vec3 position, ecs::Quat rotation = {},
                                 const QueryFilter& filter = {});

// A sphere Collider of `radius` metres, for queries.
content::Collider sphereOf(float radius);

}  // namespace candela::physics
