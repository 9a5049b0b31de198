#pragma once
// What one frame asks of the renderer. Filled by the runtime from the scene each frame.
#include <array>
#include <optional>
#include <vector>

#include "candela/render/frame_scene.h"
#include "candela/render/text_overlay.h"

namespace candela::render {

struct FrameInputs {
    std::array<float, 4> clearRadiance{0.0f, 0.0f, 0.0f, 1.0f};  // background, cd/m^2
    FrameScene scene;  // meshes and lights; its camera also sets the exposure
    // Foundation test scene: one flat HDR triangle drawn instead of the scene's meshes.
    std::optional<std::array<float, 4>> testTriangleRadiance;
    // Screen-space text drawn over the tonemapped image (text_overlay.h).
    std::vector<TextLine> text;
    // Scene time since the previous frame: how far automatic exposure adapts.
    float deltaSeconds = 1.0f / 30.0f;
};

}  // namespace candela::render
