#pragma once
// CharacterController component: a player or NPC that walks, climbs steps, stays on slopes it
// can stand on and jumps, moved by sweeping a capsule through the world (collide and slide)
// rather than by forces. PhysicsWorld moves every entity that has one at each fixed step; the
// entity's LocalTransform position is the capsule's centre (keep it a root entity).
//
//   auto& walker = registry.emplace<CharacterController>(player);
//   walker.desiredVelocity = {input.x * 4.0f, 0, input.z * 4.0f};   // game code, each frame
//   walker.jump = input.jumpPressed;
//   if (walker.grounded) ...
//
// Give the entity a capsule Collider and a kinematic RigidBody as well, and triggers see it
// and dynamic bodies are pushed by it; its own sweeps ignore it.
#include <cstdint>

#include "candela/content/components/collider.h"
#include "candela/ecs/transform_math.h"

namespace candela::physics {

struct CharacterController {
    // The capsule, metres, along world +Y.
    float radius = 0.3f;
    float height = 1.8f;            // end to end
    float stepHeight = 0.35f;       // ledges up to this high are climbed, as stairs
    float maxSlopeDegrees = 45.0f;  // steeper ground is a wall
    float skinWidth = 0.02f;        // the gap kept from every surface
    float jumpSpeed = 5.0f;         // m/s upwards when a jump starts
    float gravityScale = 1.0f;
    std::uint32_t mask = content::kAllCollisionLayers;  // the layers it collides with

    // Written by game code: the walking velocity wanted (m/s, its y is ignored) and whether
    // to jump (taken, and cleared, when the character stands on the ground).
    ecs::Vec3 desiredVelocity{};
    bool jump = false;

    // Written by physics after each step.
    bool grounded = false;
    ecs::Vec3 groundNormal{0, 1, 0};
    float verticalSpeed = 0.0f;  // m/s, positive upwards
};

}  // namespace candela::physics
