#include "candela/render/frame_scene.h"

#include <cmath>

namespace candela::render {

glm::mat4 reverseZPerspective(float verticalFov, float aspect, float nearPlane) {
    // Vulkan clip space (y down, depth 0..1) with depth = nearPlane / viewDistance.
    const float f = 1.0f / std::tan(verticalFov * 0.5f);
    glm::mat4 p(0.0f);
    p[0][0] = f / aspect;
    p[1][1] = -f;
    p[2][3] = -1.0f;
    p[3][2] = nearPlane;
    return p;
}

}  // namespace candela::render
