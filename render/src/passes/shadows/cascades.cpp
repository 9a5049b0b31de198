#include "passes/shadows/cascades.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace candela::render {

std::vector<float> practicalSplits(float nearPlane, float farPlane, uint32_t count, float lambda) {
    std::vector<float> splits(count + 1);
    for (uint32_t i = 0; i <= count; ++i) {
        const float t = float(i) / float(count);
        const float logarithmic = nearPlane * std::pow(farPlane / nearPlane, t);
        const float uniform = nearPlane + (farPlane - nearPlane) * t;
        splits[i] = lambda * logarithmic + (1.0f - lambda) * uniform;
    }
    splits.front() = nearPlane;
    splits.back() = farPlane;
    return splits;
}

glm::mat3 lightBasis(const glm::vec3& direction) {
    const glm::vec3 forward = glm::normalize(direction);
    const glm::vec3 reference =
        std::abs(forward.y) > 0.99f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    const glm::vec3 right = glm::normalize(glm::cross(reference, forward));
    const glm::vec3 up = glm::cross(forward, right);
    return glm::mat3(right, up, forward);
}

namespace {

// The world-space corners of the camera frustum between view depths a and b. The projection
// is reverse-Z with an infinite far plane: view depth z has NDC depth near / z.
std::array<glm::vec3, 8> sliceCorners(const CameraView& camera, float a, float b) {
    const glm::mat4 inverse = glm::inverse(camera.projection * camera.view);
    std::array<glm::vec3, 8> corners{};
    size_t n = 0;
    for (float depth : {a, b}) {
        const float ndcZ = camera.nearPlane / depth;
        for (float y : {-1.0f, 1.0f}) {
            for (float x : {-1.0f, 1.0f}) {
                const glm::vec4 p = inverse * glm::vec4(x, y, ndcZ, 1.0f);
                corners[n++] = glm::vec3(p) / p.w;
            }
        }
    }
    return corners;
}

float snap(float value, float step) {
    return std::floor(value / step) * step;
}

}  // namespace

CascadeView fitCascade(const CameraView& camera, float sliceNear, float sliceFar,
                       const glm::vec3& direction, uint32_t resolution, float casterNear) {
    // The sphere's radius depends only on the slice's shape, not on where the camera is or
    // where it looks: measured in view space, and rounded up so float noise cannot change it.
    const std::array<glm::vec3, 8> corners = sliceCorners(camera, sliceNear, sliceFar);
    glm::vec3 centre(0.0f);
    for (const glm::vec3& c : corners)
        centre += c;
    centre /= 8.0f;
    float radius = 0.0f;
    const glm::vec3 viewCentre = glm::vec3(camera.view * glm::vec4(centre, 1.0f));
    for (const glm::vec3& c : corners) {
        const glm::vec3 viewCorner = glm::vec3(camera.view * glm::vec4(c, 1.0f));
        radius = std::max(radius, glm::length(viewCorner - viewCentre));
    }
    radius = std::ceil(radius * 16.0f) / 16.0f;

    CascadeView out;
    out.texelWorld = 2.0f * radius / float(resolution);
    const glm::mat3 basis = lightBasis(direction);
    const glm::vec3 right = basis[0], up = basis[1], forward = basis[2];
    // Whole texels in light space: the map's texel grid stays put as the centre moves.
    const float x = snap(glm::dot(centre, right), out.texelWorld);
    const float y = snap(glm::dot(centre, up), out.texelWorld);
    const float z = glm::dot(centre, forward);
    out.farDepth = snap(z + radius, out.texelWorld) + out.texelWorld;
    // Casters toward the light, on a coarse grid (1 m) so the depth mapping rarely changes.
    out.nearDepth = std::floor(std::min(z - radius, casterNear) - 1.0f);
    out.sphere = glm::vec4(centre, radius);

    // clip.x = (right.P - x) / r, clip.y = (up.P - y) / r, clip.z = (far - forward.P) /
    // (far - near): reversed like the camera's depth (nearer the light is larger).
    const float depthRange = out.farDepth - out.nearDepth;
    glm::mat4 m(0.0f);
    for (int i = 0; i < 3; ++i) {
        m[i][0] = right[i] / radius;
        m[i][1] = up[i] / radius;
        m[i][2] = -forward[i] / depthRange;
    }
    m[3][0] = -x / radius;
    m[3][1] = -y / radius;
    m[3][2] = out.farDepth / depthRange;
    m[3][3] = 1.0f;
    out.worldToClip = m;
    return out;
}

}  // namespace candela::render
