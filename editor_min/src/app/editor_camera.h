#pragma once
// The viewport camera. It starts looking through the scene's camera; holding the right mouse
// button over the viewport detaches it into a free editor camera (mouse look, W/A/S/D/Q/E to
// move, Shift for speed) so the scene can be inspected from anywhere without editing the saved
// camera. View > Scene camera goes back. Exposure and field of view stay the scene camera's.
#include <glm/glm.hpp>

#include "candela/render/frame_scene.h"

namespace candela::editor {

class EditorCamera {
public:
    bool detached() const { return detached_; }
    void attachToScene() { detached_ = false; }

    // Reads ImGui's input for this frame (call between beginFrame and endFrame, after the
    // panels, so mouse capture by a panel is known) and moves the free camera.
    void update(const render::CameraView& sceneCamera, bool sceneHasCamera);

    // What the frame renders through: the scene camera, or the free camera with the scene
    // camera's projection and exposure.
    render::CameraView view(const render::CameraView& sceneCamera) const;

private:
    bool detached_ = false;
    glm::vec3 position_{0.0f};
    float yaw_ = 0.0f;    // radians about +Y; 0 looks along -Z
    float pitch_ = 0.0f;  // radians, clamped to +-1.5
};

}  // namespace candela::editor
