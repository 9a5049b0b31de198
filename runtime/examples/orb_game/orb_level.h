#pragma once
// Turns the level's scene-file entities into game entities: each entity's `gameData` JSON
// names its role ("orb", "pickup", "hazard", "wall", "rules") and its parameters.
#include <string>

#include "candela/content/model.h"
#include "candela/runtime/scene_world.h"

namespace orb {

// Adds the game components (and the meshes of the orb, pickups and sentinels). Returns an
// empty string, or a message naming the problem (no orb, no rules, a malformed role).
std::string spawnLevel(candela::runtime::SceneWorld& world, const std::string& levelName);

}  // namespace orb
