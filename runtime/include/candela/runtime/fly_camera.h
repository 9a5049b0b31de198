#pragma once
// A free-flying camera for windows: W/S forward and back, A/D sideways, E/Q up and down,
// shift for speed, mouse look while the right (or left) mouse button is held.
#include "candela/ecs/transform_math.h"
#include "candela/runtime/frame_context.h"
#include "candela/runtime/scene_world.h"

namespace candela::runtime {

class Application;

// Put next to a Camera and a LocalTransform; the system owns the entity's rotation.
struct FlyCamera {
    float yaw = 0.0f;    // radians about +Y; 0 looks along -Z
    float pitch = 0.0f;  // radians about the camera's +X, clamped to +-1.5
    float metresPerSecond = 3.0f;
    float fastMultiplier = 4.0f;  // while shift is held
    float radiansPerPixel = 0.003f;
};

// The rotation a camera (looking along -Z) has at yaw and pitch.
ecs::Quat flyCameraRotation(float yaw, float pitch);

// Moves every FlyCamera entity by the frame's input.
void updateFlyCameras(SceneWorld& world, const FrameContext& frame);

// Adds updateFlyCameras as an Update system that declares what it touches (writes FlyCamera
// and LocalTransform), so systems that share neither run beside it.
void addFlyCameraSystem(Application& app);

}  // namespace candela::runtime
