#pragma once
// The orb game's screens on the engine's game UI (runtime/game_ui.h): a title menu (Play,
// Quit; mouse, arrows and Enter, or the D-pad and A) that holds the clock until Play, a score
// panel in the top-right corner during play, and the result with how to restart at the end.
#include "candela/runtime/application.h"

namespace orb {

// `showTitle`: start on the title menu (the game's GameState waits in Status::Title).
void addOrbUi(candela::runtime::Application& app, bool showTitle);

}  // namespace orb
