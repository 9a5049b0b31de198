#pragma once
// The game's logic, one system per rule, run every frame on the engine's scheduler. Each
// declares the components it reads and writes (addOrbSystems): systems that conflict run in
// the order added (restart, steer, patrol, collect, referee, animate, hud); animate and hud
// share nothing they write and run side by side.
#include "candela/runtime/application.h"
#include "candela/runtime/input_actions.h"

namespace orb {

void restartSystem(candela::runtime::SceneWorld& world, const candela::runtime::FrameContext& f);
void steerSystem(candela::runtime::SceneWorld& world, const candela::runtime::FrameContext& f);
void patrolSystem(candela::runtime::SceneWorld& world, const candela::runtime::FrameContext& f);
void collectSystem(candela::runtime::SceneWorld& world, const candela::runtime::FrameContext& f);
void refereeSystem(candela::runtime::SceneWorld& world, const candela::runtime::FrameContext& f);
void mascotSystem(candela::runtime::SceneWorld& world, const candela::runtime::FrameContext& f);
void animateSystem(candela::runtime::SceneWorld& world, const candela::runtime::FrameContext& f);

// The controls, read through named actions (the registry's InputActions resource): steer_x and
// steer_z (WASD, the arrows, the D-pad and the left stick) and restart (R, Start). Returns them
// for a bindings file to rebind.
candela::runtime::InputActions& addOrbControls(candela::runtime::SceneWorld& world);

// Adds the systems above, plus one that keeps the window title as the HUD.
void addOrbSystems(candela::runtime::Application& app);

}  // namespace orb
