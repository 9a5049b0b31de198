// The camera's validation rules (content/component_validation.h): values whose projection
// would overflow are clamped with a warning.
#include <gtest/gtest.h>

#include "candela/content/component_validation.h"
#include "candela/content/components/camera.h"

namespace candela::content {
namespace {

// Issue 44 (found by the settings fuzzer): a field of view of 1e-45 rad was accepted and the
// projection's 1 / tan(fov / 2) turned the frame to NaN. A camera narrower than
// kMinVerticalFov, nearer than kMinNearPlane or an orthographic one smaller than
// kMinOrthographicHalfHeight is clamped with a warning naming the field.
TEST(CameraComponent, ProjectionsThatOverflowAreClampedWithAWarning) {
    Camera camera;
    camera.verticalFov = 1.4e-45f;
    camera.nearPlane = 1e-30f;
    const ValueProblems problems = validateCamera(camera);
    EXPECT_FALSE(anyRejected(problems));
    ASSERT_EQ(problems.size(), 2u);
    EXPECT_EQ(problems[0].field, "verticalFov");
    EXPECT_EQ(problems[1].field, "nearPlane");
    EXPECT_EQ(camera.verticalFov, kMinVerticalFov);
    EXPECT_EQ(camera.nearPlane, kMinNearPlane);
    Camera orthographic;
    orthographic.projection = Projection::Orthographic;
    orthographic.orthographicHalfHeight = 1e-40f;
    const ValueProblems ortho = validateCamera(orthographic);
    ASSERT_EQ(ortho.size(), 1u);
    EXPECT_TRUE(ortho[0].clamped);
    EXPECT_EQ(orthographic.orthographicHalfHeight, kMinOrthographicHalfHeight);
    Camera ordinary;
    EXPECT_TRUE(validateCamera(ordinary).empty());
}

}  // namespace
}  // namespace candela::content
