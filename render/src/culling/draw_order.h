#pragma once
// The order a view records its opaque draws in: nearest first, so the depth test rejects the
// fragments of what lies behind before their shading runs (a CPU rasterizer shades every
// fragment that passes it, and the G-buffer writes up to eight targets each).
#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "culling/draw_bounds.h"

namespace candela::render {

// The indices of the draws `visible` does not cull (kDrawCulled), by the distance from `eye`
// to their world box (0 inside it), nearest first; ties keep the scene's order.
std::vector<uint32_t> nearestFirst(std::span<const uint8_t> visible,
                                   std::span<const WorldBounds> bounds, const glm::vec3& eye);

}  // namespace candela::render
