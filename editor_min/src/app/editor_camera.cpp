#include "app/editor_camera.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace candela::editor {

namespace {

constexpr float kRadiansPerPixel = 0.003f;
constexpr float kMetresPerSecond = 3.0f;
constexpr float kFastMultiplier = 4.0f;

glm::vec3 forwardOf(float yaw, float pitch) {
    return {-std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch)};
}

}  // namespace

void EditorCamera::update(const render::CameraView& sceneCamera, bool sceneHasCamera) {
    const ImGuiIO& io = ImGui::GetIO();
    const bool looking = io.MouseDown[1] && !io.WantCaptureMouse;
    if (!looking) return;
    if (!detached_) {
        // Start where the scene camera is, looking where it looks.
        const glm::mat4 world = glm::inverse(sceneCamera.view);
        position_ = sceneHasCamera ? glm::vec3(world[3]) : glm::vec3(0.0f, 1.0f, 5.0f);
        const glm::vec3 forward =
            sceneHasCamera ? -glm::normalize(glm::vec3(world[2])) : glm::vec3(0, 0, -1);
        pitch_ = std::asin(std::clamp(forward.y, -1.0f, 1.0f));
        yaw_ = std::atan2(-forward.x, -forward.z);
        detached_ = true;
    }
    yaw_ -= io.MouseDelta.x * kRadiansPerPixel;
    pitch_ = std::clamp(pitch_ - io.MouseDelta.y * kRadiansPerPixel, -1.5f, 1.5f);
    const glm::vec3 forward = forwardOf(yaw_, pitch_);
    const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
    glm::vec3 move(0.0f);
    // ImGui 1.86 with the GLFW backend indexes keys by GLFW key code.
    if (io.KeysDown[GLFW_KEY_W]) move += forward;
    if (io.KeysDown[GLFW_KEY_S]) move -= forward;
    if (io.KeysDown[GLFW_KEY_D]) move += right;
    if (io.KeysDown[GLFW_KEY_A]) move -= right;
    if (io.KeysDown[GLFW_KEY_E]) move.y += 1.0f;
    if (io.KeysDown[GLFW_KEY_Q]) move.y -= 1.0f;
    const float speed = kMetresPerSecond * (io.KeyShift ? kFastMultiplier : 1.0f);
    if (glm::length(move) > 0.0f) position_ += glm::normalize(move) * speed * io.DeltaTime;
}

render::CameraView EditorCamera::view(const render::CameraView& sceneCamera) const {
    if (!detached_) return sceneCamera;
    render::CameraView v = sceneCamera;
    v.position = position_;
    v.view = glm::lookAt(position_, position_ + forwardOf(yaw_, pitch_), glm::vec3(0, 1, 0));
    return v;
}

}  // namespace candela::editor
