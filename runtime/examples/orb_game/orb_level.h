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

// Loads the glTF at `modelPath` as the level's mascot (a Mascot component), standing on the
// north wall and facing the player. Returns an empty string, or the problem (the loader's
// messages are in `diagnostics`; a model without clips is refused).
std::string spawnMascot(candela::runtime::SceneWorld& world, const std::string& modelPath,
                        candela::content::Diagnostics& diagnostics);

}  // namespace orb
