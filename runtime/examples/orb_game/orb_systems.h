#pragma once
// The game's logic, one system per rule, run every frame on the engine's scheduler. Each
// declares the components it reads and writes (addOrbSystems): systems that conflict run in
// the order added (restart, steer, patrol, collect, referee, animate, hud); animate and hud
// share nothing they write and run side by side.
#include "candela/runtime/application.h"

namespace orb {

void restartSystem(candela::runtime::SceneWorld& world, const candela::runtime::FrameContext& f);
void steerSystem(candela::runtime::SceneWorld& world, const candela::runtime::FrameContext& f);
void patrolSystem(candela::runtime::SceneWorld& world, const candela::runtime::FrameContext& f);
void collectSystem(candela::runtime::SceneWorld& world, const candela::runtime::FrameContext& f);
void refereeSystem(candela::runtime::SceneWorld& world, const candela::runtime::FrameContext& f);
void mascotSystem(candela::runtime::SceneWorld& world, const candela::runtime::FrameContext& f);
void animateSystem(candela::runtime::SceneWorld& world, const candela::runtime::FrameContext& f);

// Adds the systems above, plus one that keeps the window title as the HUD.
void addOrbSystems(candela::runtime::Application& app);

}  // namespace orb
