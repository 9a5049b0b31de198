#pragma once
// The physics world drawn as lines, for --physics-debug: every collider's outline as Bullet
// sees it (what collides, whatever the mesh shows) and the contact points of the last step.
#include <vector>

#include "candela/ecs/transform_math.h"
#include "candela/physics/physics_world.h"

namespace candela::physics {

enum class DebugLineKind : unsigned char { Collider, Trigger, Contact };

struct DebugLine {
    ecs::Vec3 from{};
    ecs::Vec3 to{};
    DebugLineKind kind = DebugLineKind::Collider;
};

// World-space segments; `out` is cleared first.
void debugLines(const PhysicsWorld& world, std::vector<DebugLine>& out);

}  // namespace candela::physics
