#pragma once
// The world-space ray under a point of the screen, for picking and aiming:
//
//   if (auto ray = screenRay(world.registry, camera, mouseX, mouseY, frame.width, frame.height))
//       if (auto hit = physics::raycast(world.physics(), ray->origin, ray->direction, 100.0f))
//           select(hit->entity);
#include <cstdint>
#include <optional>

#include "candela/ecs/registry.h"
#include "candela/ecs/transform_math.h"

namespace candela::runtime {

struct Ray {
    ecs::Vec3 origin{};
    ecs::Vec3 direction{0, 0, -1};  // unit
};

// Through the point (x, y) of a width x height view (pixels, from the top-left corner; a
// pixel's centre is at +0.5) seen from `camera`, an entity with a content::Camera and a
// WorldTransform, projected as the renderer draws it (a perspective of the camera's vertical
// field of view; its scale ignored). The origin is the camera's position. Nullopt for a view of
// no size, a camera entity without those components, or a non-finite transform.
std::optional<Ray> screenRay(const ecs::Registry& registry, ecs::Entity camera, float x, float y,
                             std::uint32_t width, std::uint32_t height);

}  // namespace candela::runtime
