#include "passes/sky_occlusion/sky_occlusion_directions.h"

#include <cmath>

namespace candela::render {

namespace {
constexpr float kGoldenAngle = 2.39996323f;  // pi (3 - sqrt 5)
}

glm::vec3 skyOcclusionDirection(uint32_t i, uint32_t n) {
    const float y = (float(i) + 0.5f) / float(n);
    const float r = std::sqrt(std::max(0.0f, 1.0f - y * y));
    const float phi = float(i) * kGoldenAngle;
    return {r * std::cos(phi), y, r * std::sin(phi)};
}

glm::mat4 skyOcclusionView(const glm::vec3& d, const glm::vec3& centre, float radius) {
    // The same basis as common/sky_occlusion.glsl's skyOcclusionBasis.
    const glm::vec3 helper = std::abs(d.y) > 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::vec3 right = glm::normalize(glm::cross(helper, d));
    const glm::vec3 up = glm::cross(d, right);
    glm::mat4 m(0.0f);
    for (int k = 0; k < 3; ++k) {
        m[k][0] = right[k] / radius;
        m[k][1] = up[k] / radius;
        m[k][2] = d[k] / (4.0f * radius);
    }
    m[3][0] = -glm::dot(right, centre) / radius;
    m[3][1] = -glm::dot(up, centre) / radius;
    m[3][2] = (radius - glm::dot(d, centre)) / (4.0f * radius);
    m[3][3] = 1.0f;
    return m;
}

}  // namespace candela::render
