#pragma once
// The game's logic, one system per rule. Each runs every frame in the order addOrbSystems
// adds them: restart, steer, patrol, collect, referee, animate.
#include "candela/runtime/application.h"

namespace orb {

void restartSystem(candela::runtime::SceneWorld& world, const candela::runtime::FrameContext& f);
void steerSystem(candela::runtime::SceneWorld& world, const candela::runtime::FrameContext& f);
void patrolSystem(candela::runtime::SceneWorld& world, const candela::runtime::FrameContext& f);
void collectSystem(candela::runtime::SceneWorld& world, const candela::runtime::FrameContext& f);
void refereeSystem(candela::runtime::SceneWorld& world, const candela::runtime::FrameContext& f);
void animateSystem(candela::runtime::SceneWorld& world, const candela::runtime::FrameContext& f);

// Adds the systems above, plus one that keeps the window title as the HUD.
void addOrbSystems(candela::runtime::Application& app);

}  // namespace orb
