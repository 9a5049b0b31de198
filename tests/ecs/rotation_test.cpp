// lookAtRotation and fromToRotation (issue 47): what they should do, checked on the vectors.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "candela/ecs/rotation.h"

namespace candela::ecs {
namespace {

Vec3 unit(Vec3 v) {
    return v * (1.0f / length(v));
}

void expectNear(Vec3 a, Vec3 b, float tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(Rotation, LookAtTurnsMinusZTowardsTheTargetWithoutRolling) {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> coordinate(-10.0f, 10.0f);
    for (int i = 0; i < 200; ++i) {
        const Vec3 position{coordinate(random), coordinate(random), coordinate(random)};
        const Vec3 target{coordinate(random), coordinate(random), coordinate(random)};
        const std::optional<Quat> q = lookAtRotation(position, target);
        ASSERT_TRUE(q.has_value());
        expectNear(rotate(*q, {0, 0, -1}), unit(target - position), 1e-5f);
        EXPECT_NEAR(rotate(*q, {1, 0, 0}).y, 0.0f, 1e-5f) << "its right stays level";
        EXPECT_GT(rotate(*q, {0, 1, 0}).y, -1e-6f) << "never upside down";
    }
    EXPECT_FALSE(lookAtRotation({1, 2, 3}, {1, 2, 3}).has_value());
    expectNear(rotate(*lookAtRotation({0, 0, 0}, {0, 5, 0}), {0, 0, -1}), {0, 1, 0}, 1e-6f);
}

TEST(Rotation, FromToTurnsOneDirectionOntoTheOther) {
    std::mt19937 random(11);
    std::uniform_real_distribution<float> coordinate(-1.0f, 1.0f);
    for (int i = 0; i < 200; ++i) {
        const Vec3 from{coordinate(random), coordinate(random), coordinate(random)};
        const Vec3 to{coordinate(random), coordinate(random), coordinate(random)};
        expectNear(rotate(fromToRotation(from, to), unit(from)), unit(to), 1e-5f);
    }
    // Opposite directions: half a turn about a perpendicular axis.
    for (const Vec3 from : {Vec3{1, 0, 0}, Vec3{0, 2, 0}, Vec3{0, 0, -3}, Vec3{1, 1, 1}}) {
        const Quat q = fromToRotation(from, from * -1.0f);
        expectNear(rotate(q, unit(from)), unit(from) * -1.0f, 1e-6f);
        EXPECT_NEAR(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w, 1.0f, 1e-6f);
    }
    // The same direction: no turn. A zero direction: the identity.
    const Quat same = fromToRotation({0, 3, 0}, {0, 1, 0});
    EXPECT_NEAR(same.w, 1.0f, 1e-7f);
    EXPECT_EQ(fromToRotation({0, 0, 0}, {1, 0, 0}), Quat{});
}

}  // namespace
}  // namespace candela::ecs
