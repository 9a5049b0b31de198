#pragma once
// What happened between bodies during one PhysicsWorld::update(): contacts between solid
// colliders and overlaps with triggers, each as it began, stayed or ended. A pair is reported
// once per update in each phase it went through (a touch that began and ended within one
// frame's steps gives Begin and End), with `a` the entity made first (lower index).
#include <cstdint>
#include <vector>

#include "candela/ecs/entity.h"
#include "candela/ecs/transform_math.h"

namespace candela::physics {

enum class ContactPhase : std::uint8_t { Begin, Stay, End };

struct ContactEvent {
    ecs::Entity a = ecs::kNullEntity;
    ecs::Entity b = ecs::kNullEntity;
    ContactPhase phase = ContactPhase::Begin;
    ecs::Vec3 point{};     // world space, the deepest contact point (End: the last one seen)
    ecs::Vec3 normal{};    // world space, from b towards a
    float impulse = 0.0f;  // N s, the largest normal impulse the solver applied in the update
};

struct TriggerEvent {
    ecs::Entity trigger = ecs::kNullEntity;
    ecs::Entity other = ecs::kNullEntity;
    ContactPhase phase = ContactPhase::Begin;
};

struct PhysicsEvents {
    std::vector<ContactEvent> contacts;
    std::vector<TriggerEvent> triggers;
};

}  // namespace candela::physics
