#pragma once
// RigidBody component: how an entity with a Collider moves under physics (physics/README.md).
// An entity with a Collider and no RigidBody is static level geometry.
//
//   "rigidBody": {"type": "dynamic", "mass": 1.0, "friction": 0.5, "restitution": 0.0}
#include <cstdint>

#include "candela/ecs/transform_math.h"

namespace candela::content {

// Static: never moves (moving its transform teleports it). Dynamic: moved by forces and
// contacts. Kinematic: moved by game code through its LocalTransform; pushes dynamic bodies
// and is not pushed back.
enum class BodyType : std::uint8_t { Static, Dynamic, Kinematic };

struct RigidBody {
    BodyType type = BodyType::Dynamic;
    float mass = 1.0f;             // kg, dynamic bodies only (> 0)
    float friction = 0.5f;         // Coulomb coefficient, >= 0; a pair uses sqrt(a * b)
    float restitution = 0.0f;      // 0..1; a pair uses the larger of the two
    float linearDamping = 0.0f;    // 0..1, fraction of linear velocity lost per second
    float angularDamping = 0.05f;  // 0..1, the same for angular velocity
    float gravityScale = 1.0f;     // multiplies the world's gravity for this body
    // Velocities in world space. Physics writes them after every step; game code may set them
    // (registry.patch) and the next step starts from the values it wrote.
    ecs::Vec3 linearVelocity{};   // m/s
    ecs::Vec3 angularVelocity{};  // rad/s
    bool canSleep = true;         // a body at rest stops being simulated until something touches it
    // Swept collision for fast, small bodies (a bullet through a thin wall).
    bool continuousCollision = false;
    bool sleeping = false;  // written by physics: the body is at rest and not simulated

    bool operator==(const RigidBody&) const = default;
};

}  // namespace candela::content
