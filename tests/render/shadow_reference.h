#pragma once
// Test and report support: CPU ray-cast shadows of axis-aligned boxes, the reference the
// rendered shadows are measured against (hard: one ray to a point or toward the sun; soft:
// many rays to points on a sphere light's surface).
#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <span>

#include "box_ray.h"

namespace candela::render::test {

// Whether the segment a + t (b - a), t in (1e-4, 1), passes through the box.
inline bool segmentHitsBox(const glm::vec3& a, const glm::vec3& b, const Box& box) {
    return rayHitsBox(a, b - a, box, 1e-4f, 1.0f);
}

inline bool segmentHitsAny(const glm::vec3& a, const glm::vec3& b, std::span<const Box> boxes) {
    return std::any_of(boxes.begin(), boxes.end(),
                       [&](const Box& box) { return segmentHitsBox(a, b, box); });
}

// Share of a sphere light's visible disk that p sees past the boxes: `samples` points on the
// disk facing p (a Fibonacci spiral, uniform by area), each tested with one ray.
inline float sphereLightVisibility(const glm::vec3& p, const glm::vec3& centre, float radius,
                                   std::span<const Box> boxes, int samples) {
    const glm::vec3 w = glm::normalize(centre - p);
    const glm::vec3 helper = std::abs(w.y) > 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::vec3 u = glm::normalize(glm::cross(helper, w));
    const glm::vec3 v = glm::cross(w, u);
    int visible = 0;
    for (int i = 0; i < samples; ++i) {
        const float r = radius * std::sqrt((float(i) + 0.5f) / float(samples));
        const float phi = float(i) * 2.39996323f;  // golden angle
        const glm::vec3 q = centre + r * (std::cos(phi) * u + std::sin(phi) * v);
        visible += segmentHitsAny(p, q, boxes) ? 0 : 1;
    }
    return float(visible) / float(samples);
}

}  // namespace candela::render::test
