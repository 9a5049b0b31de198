#pragma once
// Test support: axis-aligned boxes and the slab test of a ray against one, shared by the CPU
// references that trace rays past boxes (shadow_reference.h, sky_occlusion_scene.h,
// ambient_occlusion_scene.h, ssr_scene.h).
#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <optional>
#include <utility>

namespace candela::render::test {

struct Box {
    glm::vec3 lo, hi;
};

// Where the ray o + t d, t in [tMin, tMax], enters the box (the first t in range inside it),
// if it meets it.
inline std::optional<float> rayBoxEntry(const glm::vec3& o, const glm::vec3& d, const Box& box,
                                        float tMin, float tMax) {
    for (int i = 0; i < 3; ++i) {
        if (std::abs(d[i]) < 1e-12f) {
            if (o[i] < box.lo[i] || o[i] > box.hi[i]) return std::nullopt;
            continue;
        }
        float u = (box.lo[i] - o[i]) / d[i], v = (box.hi[i] - o[i]) / d[i];
        if (u > v) std::swap(u, v);
        tMin = std::max(tMin, u);
        tMax = std::min(tMax, v);
        if (tMin > tMax) return std::nullopt;
    }
    return tMin;
}

// Whether the ray o + t d, t in [tMin, tMax], passes through the box.
inline bool rayHitsBox(const glm::vec3& o, const glm::vec3& d, const Box& box, float tMin,
                       float tMax) {
    return rayBoxEntry(o, d, box, tMin, tMax).has_value();
}

}  // namespace candela::render::test
