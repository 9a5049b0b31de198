#pragma once
// A view's frustum as planes in world space, from its world-to-clip matrix, and the box test
// the geometry passes skip draws by. Planes by Gribb and Hartmann 2001, "Fast Extraction of
// Viewing Frustum Planes from the World-View-Projection Matrix".
#include <array>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "culling/draw_bounds.h"

namespace candela::render {

struct ViewFrustum {
    // Left, right, bottom, top, near: inside where dot(plane, (p, 1)) >= 0. No far plane: the
    // engine's projections (reverse-Z, infinite far) have none. All zero (the default): a
    // frustum that holds everything.
    std::array<glm::vec4, 5> planes{};
};

// The frustum of a perspective view whose clip-space w is the distance along its forward
// axis and whose depth is near / w (reverse-Z). `ndcMargin` widens the sides by that much of
// normalized device coordinates (2 is the whole width): TAA's jitter moves the image by up to
// a pixel, 2 / width, after this test.
ViewFrustum viewFrustumOf(const glm::mat4& worldToClip, glm::vec2 ndcMargin = glm::vec2(0.0f));

// False only when the box lies wholly outside one plane: a box that straddles two planes
// outside the frustum's corner is kept (conservative, never wrong).
bool intersects(const ViewFrustum& frustum, const WorldBounds& box);

}  // namespace candela::render
