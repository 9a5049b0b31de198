#include "culling/view_frustum.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace candela::render {

ViewFrustum viewFrustumOf(const glm::mat4& worldToClip, glm::vec2 ndcMargin) {
    // Rows of the matrix: clip = (dot(r0, p), dot(r1, p), dot(r2, p), dot(r3, p)).
    const glm::mat4 rows = glm::transpose(worldToClip);
    const glm::vec4 x = rows[0], y = rows[1], z = rows[2], w = rows[3];
    ViewFrustum f;
    // -w (1 + m) <= x <= w (1 + m), the same for y; depth near / w <= 1: w >= z (clip z is
    // the near distance).
    f.planes[0] = w * (1.0f + ndcMargin.x) + x;
    f.planes[1] = w * (1.0f + ndcMargin.x) - x;
    f.planes[2] = w * (1.0f + ndcMargin.y) + y;
    f.planes[3] = w * (1.0f + ndcMargin.y) - y;
    f.planes[4] = w - z;
    return f;
}

bool intersects(const ViewFrustum& frustum, const WorldBounds& box) {
    for (const glm::vec4& plane : frustum.planes) {
        const glm::vec3 n(plane);
        // The box's corner furthest along the plane's normal.
        const float reach = glm::dot(glm::abs(n), box.extent);
        if (glm::dot(n, box.centre) + plane.w < -reach) return false;
    }
    return true;
}

}  // namespace candela::render
