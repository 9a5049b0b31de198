#pragma once
// Rotations game code asks for by what they should do, not by their quaternion:
//
//   t.rotation = lookAtRotation(t.position, player).value_or(t.rotation);  // face the player
//   arrow.rotation = fromToRotation({0, 0, -1}, velocity);                  // fly nose first
//
// Entities look along their local -Z with +Y up, as cameras, spot lights and glTF do.
#include <optional>

#include <candela/ecs/transform_math.h>

namespace candela::ecs {

// The rotation that turns an entity at `position` to look (its -Z) at `target`, +Y up: a yaw
// about +Y, then a pitch about the turned +X, so it never rolls. Straight up or down it
// faces with yaw 0. Nullopt when the target is (within 1e-6 m of) the position. Computed in
// double precision: scene files' "lookAt" use it, and it gives the same bits everywhere.
std::optional<Quat> lookAtRotation(Vec3 position, Vec3 target);

// The shortest-arc rotation that turns direction `from` onto direction `to` (neither need be
// unit). Opposite directions turn half a circle about an axis perpendicular to `from`; a zero
// or non-finite direction gives the identity.
Quat fromToRotation(Vec3 from, Vec3 to);

}  // namespace candela::ecs
