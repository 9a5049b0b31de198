#pragma once
// An AnimationPlayer's state to and from a scene file's "animation" block (SceneAnimation):
// clips by name (by index when the clip has no unique name).
#include <string>

#include "candela/content/components/animation.h"
#include "candela/content/scene_file.h"

namespace candela::content {

// What restoring found wrong: the JSON pointer below the "animation" block ("/clip",
// "/crossfade/clip") and the message.
struct SceneAnimationProblem {
    std::string pointer;
    std::string message;
};

// Sets `player` (its model already set) to `state`. On a problem (a clip the model lacks) the
// player is left reset: its first clip from time 0, looping.
std::optional<SceneAnimationProblem> restoreAnimationPlayer(const SceneAnimation& state,
                                                            AnimationPlayer& player);

// The player's state; nullopt when it plays no clip.
std::optional<SceneAnimation> captureAnimationPlayer(const AnimationPlayer& player);

}  // namespace candela::content
