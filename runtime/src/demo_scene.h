#pragma once
// `candela demo`: the demo level. A colonnaded hall built from the engine's own primitives,
// the shared sample models (the damaged helmet, the metal/rough sphere grid), hundreds of
// animated coloured point lights, a lamp bulb (sphere light), neon tubes (tube lights),
// back-lit subsurface panels, toon (Legacy diffuse/specular) figures and an HDR sky.
// Headless runs follow a scripted camera path by scene time; windows fly (WASD + mouse).
#include <array>
#include <cstdint>

#include "candela/content/diagnostics.h"
#include "candela/runtime/camera_path.h"
#include "candela/runtime/frame_context.h"
#include "candela/runtime/scene_world.h"

namespace candela::runtime {

class Application;

// A dim blue night behind the scene, cd/m^2 (until the renderer draws the Sky component).
inline constexpr std::array<float, 4> kDemoBackgroundRadiance = {0.02f, 0.03f, 0.06f, 1.0f};

// Animated coloured point lights (besides the bulb, the tubes and the panel back-lights).
inline constexpr uint32_t kDemoAnimatedLights = 288;

// Fills `world`. Missing sample models are reported in `diagnostics` and left out.
void buildDemoScene(SceneWorld& world, content::Diagnostics& diagnostics);

// The tour the camera takes in headless runs (and in a window until the user flies).
const CameraPath& demoCameraPath();

// Moves the animated lights to their positions at `seconds`.
void animateDemoLights(SceneWorld& world, double seconds);

// Headless: places the camera on the path at the frame's time. In a window: the path plays
// until a movement key or mouse button is used, then the camera becomes a FlyCamera (moved by
// the fly camera system, fly_camera.h).
void updateDemoCamera(SceneWorld& world, const FrameContext& frame);

// The demo's systems, in this order: the drifting lights (declared: they read their drift and
// write LocalTransform), the camera (exclusive: taking over adds a FlyCamera), fly cameras.
void addDemoSystems(Application& app);

}  // namespace candela::runtime
