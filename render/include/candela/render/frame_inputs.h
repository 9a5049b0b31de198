#pragma once
// What one frame asks of the renderer. Filled by the runtime from the scene each frame.
#include <array>

namespace candela::render {

struct FrameInputs {
    float ev100 = 0.0f;  // exposure, from the camera (physical or manual)
    // Foundation test scene: a clear colour and one flat triangle, both HDR radiance (cd/m^2).
    std::array<float, 4> clearRadiance{0.0f, 0.0f, 0.0f, 1.0f};
    std::array<float, 4> triangleRadiance{1.0f, 1.0f, 1.0f, 1.0f};
};

}  // namespace candela::render
