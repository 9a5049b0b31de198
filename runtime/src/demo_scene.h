#pragma once
// `candela demo`: the demo level. A colonnaded hall built from the engine's own primitives,
// the shared sample models (the damaged helmet, the metal/rough sphere grid), hundreds of
// animated coloured point lights, a lamp bulb (sphere light), neon tubes (tube lights),
// back-lit subsurface panels, toon (Legacy diffuse/specular) figures, and outside it a meadow
// under a physically based sky (an Atmosphere) whose sun crosses the day as the tour runs.
// Headless runs follow a scripted camera path by scene time; windows fly (WASD + mouse).
#include <array>
#include <cstdint>

#include "candela/content/diagnostics.h"
#include "candela/runtime/camera_path.h"
#include "candela/runtime/frame_context.h"
#include "candela/runtime/scene_world.h"

namespace candela::runtime {

class Application;

// A dim blue night behind the scene, cd/m^2: what a run without the atmosphere's sky (a
// renderer that skips it) shows behind the hall.
inline constexpr std::array<float, 4> kDemoBackgroundRadiance = {0.02f, 0.03f, 0.06f, 1.0f};

// The day cycle over the hall (issue 16): the atmosphere's time of day (hours, solar time)
// starts at kDemoDayStartHours and advances kDemoDayHoursPerSecond per second of scene time,
// starting again with the camera path's loop (11:00 to 19:00 over the 32 s tour).
// --time-of-day HH:MM holds the sun still at that time instead. The day starts at 11:00 so
// that the tour's high view back over the hall (20 s) sees the sun at 16:00, low enough to
// shine through the west windows in shafts across the dusty hall (issue 17's demo; at 14:00
// the sun comes steeply through every skylight and the dust reads as one glow:
// render/README.md "Volumetric lighting"), and the look up at the power lines ends in the
// evening light.
inline constexpr float kDemoDayStartHours = 11.0f;
inline constexpr float kDemoDayHoursPerSecond = 0.25f;

// Animated coloured point lights (besides the bulb, the tubes and the panel back-lights).
inline constexpr uint32_t kDemoAnimatedLights = 288;

// Fills `world`. Missing sample models are reported in `diagnostics` and left out.
void buildDemoScene(SceneWorld& world, content::Diagnostics& diagnostics);

// The tour the camera takes in headless runs (and in a window until the user flies).
const CameraPath& demoCameraPath();

// The atmosphere's time of day at `seconds` of scene time (hours since solar midnight).
float demoTimeOfDay(double seconds);

// Moves the animated lights to their positions at `seconds`.
void animateDemoLights(SceneWorld& world, double seconds);

// Headless: places the camera on the path at the frame's time. In a window: the path plays
// until a movement key or mouse button is used, then the camera becomes a FlyCamera (moved by
// the fly camera system, fly_camera.h).
void updateDemoCamera(SceneWorld& world, const FrameContext& frame);

// The demo's systems, in this order: the fox, the drifting lights (declared: they read their
// drift and write LocalTransform), the day cycle (writes the Atmosphere), the camera (exclusive:
// taking over adds a FlyCamera), fly cameras.
void addDemoSystems(Application& app);

}  // namespace candela::runtime
