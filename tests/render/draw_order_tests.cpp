// The G-buffer's draw order (render/src/culling/draw_order.h): nearest first, culled draws left
// out, ties and boxes around the eye in the scene's order, non-finite boxes last.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "culling/draw_order.h"
#include "culling/draws_in_view.h"

using namespace candela::render;

namespace {

WorldBounds box(glm::vec3 centre, float half) {
    return {centre, glm::vec3(half), half * std::sqrt(3.0f)};
}

}  // namespace

TEST(DrawOrder, NearestFirstLeavesCulledDrawsOut) {
    const std::vector<WorldBounds> bounds = {
        box({0.0f, 0.0f, -10.0f}, 1.0f),  // 9 m away
        box({0.0f, 0.0f, -3.0f}, 1.0f),   // 2 m
        box({0.0f, 0.0f, -50.0f}, 1.0f),  // culled
        box({0.0f, 0.0f, 0.0f}, 5.0f),    // around the eye: 0
        box({0.0f, 0.0f, -2.5f}, 0.5f),   // 2 m, after draw 1 (a tie)
    };
    const std::vector<uint8_t> visible = {0, 0, kDrawCulled, 1, 0};
    EXPECT_EQ(nearestFirst(visible, bounds, glm::vec3(0.0f)), (std::vector<uint32_t>{3, 1, 4, 0}));
}

TEST(DrawOrder, ANonFiniteBoxGoesLast) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const std::vector<WorldBounds> bounds = {box({nan, 0.0f, 0.0f}, 1.0f),
                                             box({0.0f, 0.0f, -4.0f}, 1.0f)};
    const std::vector<uint8_t> visible = {0, 0};
    EXPECT_EQ(nearestFirst(visible, bounds, glm::vec3(0.0f)), (std::vector<uint32_t>{1, 0}));
}
