#pragma once
// `candela demo`: the best scene the engine can show today, built from its own primitives and
// the shared sample models. (The full demo level of issue 9 replaces it.)
#include <array>

#include "candela/content/diagnostics.h"
#include "candela/runtime/scene_world.h"

namespace candela::runtime {

// A dim blue night behind the scene, cd/m^2.
inline constexpr std::array<float, 4> kDemoBackgroundRadiance = {0.02f, 0.03f, 0.06f, 1.0f};

// Fills `world`. Missing sample models are reported in `diagnostics` and left out.
void buildDemoScene(SceneWorld& world, content::Diagnostics& diagnostics);

// Moves the animated lights to their positions at `seconds`.
void animateDemoScene(SceneWorld& world, double seconds);

}  // namespace candela::runtime
