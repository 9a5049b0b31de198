// Frustum culling without a device: the planes of the camera's reverse-Z projection and of a
// shadow face's, boxes in and out of them, and the margin TAA's jitter needs.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "candela/render/frame_scene.h"
#include "culling/view_frustum.h"

using namespace candela::render;

namespace {

WorldBounds box(glm::vec3 centre, float half) {
    WorldBounds b;
    b.centre = centre;
    b.extent = glm::vec3(half);
    b.radius = half * 1.7320508f;
    return b;
}

// A 90-degree square view looking down -Z from the origin, near plane 0.1.
glm::mat4 squareView() {
    return reverseZPerspective(glm::radians(90.0f), 1.0f, 0.1f) *
           glm::lookAt(glm::vec3(0.0f), glm::vec3(0, 0, -1), glm::vec3(0, 1, 0));
}

}  // namespace

TEST(ViewFrustum, BoxesInsideOrStraddlingAreKept) {
    const ViewFrustum f = viewFrustumOf(squareView());
    EXPECT_TRUE(intersects(f, box({0, 0, -5}, 0.5f)));
    // Far away: the projection has no far plane.
    EXPECT_TRUE(intersects(f, box({0, 0, -1e6f}, 1.0f)));
    // Across the right side (x = -z): centre outside by 0.3, half size 0.5.
    EXPECT_TRUE(intersects(f, box({5.3f, 0, -5}, 0.5f)));
    // Around the eye: across the near plane.
    EXPECT_TRUE(intersects(f, box({0, 0, 0}, 0.5f)));
}

TEST(ViewFrustum, BoxesWhollyOutsideOnePlaneAreCulled) {
    const ViewFrustum f = viewFrustumOf(squareView());
    EXPECT_FALSE(intersects(f, box({0, 0, 5}, 0.5f)));  // behind the eye
    // Right of x = -z: the box's nearest corner (6, -5.5) is 0.5 past it.
    EXPECT_FALSE(intersects(f, box({6.5f, 0, -5}, 0.5f)));
    EXPECT_FALSE(intersects(f, box({-6.5f, 0, -5}, 0.5f)));
    EXPECT_FALSE(intersects(f, box({0, 6.5f, -5}, 0.5f)));  // above
    EXPECT_FALSE(intersects(f, box({0, -6.5f, -5}, 0.5f)));
    // Touching the side at a corner, (5.5, -5.5): kept.
    EXPECT_TRUE(intersects(f, box({6.0f, 0, -5}, 0.5f)));
    EXPECT_FALSE(intersects(f, box({0, 0, -0.04f}, 0.02f)));  // in front of the near plane
}

TEST(ViewFrustum, TheMarginKeepsBoxesJustOutsideTheEdge) {
    // The nearest corner (5.7, -5.5) 0.2 past the right side; a margin of 0.1 NDC (0.55 m
    // there) keeps it.
    const WorldBounds justOutside = box({6.2f, 0, -5}, 0.5f);
    EXPECT_FALSE(intersects(viewFrustumOf(squareView()), justOutside));
    EXPECT_TRUE(intersects(viewFrustumOf(squareView(), {0.1f, 0.1f}), justOutside));
    // The vertical margin does not widen the sides.
    EXPECT_FALSE(intersects(viewFrustumOf(squareView(), {0.0f, 0.1f}), justOutside));
}

TEST(ViewFrustum, PointsTheProjectionKeepsAreKeptAndPointsOffItsSidesCulled) {
    // Any projection, here OpenGL's with a far plane: every point inside its clip volume is
    // kept, every point beyond a side (or behind the eye) is culled, on a grid of points.
    const glm::mat4 m = glm::perspective(glm::radians(70.0f), 1.5f, 0.2f, 50.0f) *
                        glm::lookAt(glm::vec3(1, 2, 3), glm::vec3(0, 0, 0), glm::vec3(0, 1, 0));
    const ViewFrustum f = viewFrustumOf(m);
    int kept = 0, culled = 0;
    for (int x = -10; x <= 10; ++x) {
        for (int y = -10; y <= 10; ++y) {
            for (int z = -10; z <= 10; ++z) {
                const glm::vec3 p(0.7f * float(x), 0.7f * float(y), 0.7f * float(z));
                const glm::vec4 c = m * glm::vec4(p, 1.0f);
                const bool inside =
                    std::abs(c.x) <= c.w && std::abs(c.y) <= c.w && c.z >= -c.w && c.z <= c.w;
                const bool offASide =
                    c.w < 0.0f || std::abs(c.x) > 1.01f * c.w || std::abs(c.y) > 1.01f * c.w;
                if (inside) {
                    EXPECT_TRUE(intersects(f, box(p, 0.0f))) << p.x << " " << p.y << " " << p.z;
                    ++kept;
                } else if (offASide) {
                    EXPECT_FALSE(intersects(f, box(p, 0.0f))) << p.x << " " << p.y << " " << p.z;
                    ++culled;
                }
            }
        }
    }
    EXPECT_GT(kept, 100);
    EXPECT_GT(culled, 100);
}
