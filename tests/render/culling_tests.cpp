// Frustum culling in a rendered frame: draws outside the camera's view are not recorded and
// change no pixel; a point light's cube faces draw only the casters each face sees, and the
// frame is the one every view drawing every draw gives (RendererOptions::culling off).
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "test_scene.h"

using namespace candela::render;
using namespace candela::render::test;

namespace {

// A white floor and a box on it under a point light, seen from above and in front; `behind`
// more boxes behind the camera, out of the light's reach.
TestScene floorAndBox(int behind) {
    TestScene scene;
    scene.width = scene.height = 64;
    scene.add(candela::content::makePlane(8.0f, 4), lambertWhite());
    scene.add(candela::content::makeBox({0.5f, 0.4f, 0.5f}), lambertWhite(),
              glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.4f, 0.0f)));
    for (int i = 0; i < behind; ++i) {
        scene.add(candela::content::makeBox({0.5f, 0.5f, 0.5f}), lambertWhite(),
                  glm::translate(glm::mat4(1.0f), glm::vec3(float(i) * 2.0f, 5.0f, 30.0f)));
    }
    scene.lookAt({0.0f, 5.0f, 3.5f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f});
    LightInstance light = pointLight({0.0f, 2.0f, 0.0f}, 2000.0f, 6.0f);
    light.light.castShadows = true;
    scene.lights = {light};
    return scene;
}

}  // namespace

TEST(Culling, DrawsOutsideTheViewAreCulledAndChangeNoPixel) {
    RendererOptions options;
    RendererStats without, with;
    const CapturedFrame alone = floorAndBox(0).render(sharedContext(), options, &without);
    const CapturedFrame crowded = floorAndBox(3).render(sharedContext(), options, &with);
    EXPECT_EQ(without.draws, 2u);
    EXPECT_EQ(without.drawsCulled, 0u);
    EXPECT_EQ(with.draws, 5u);
    EXPECT_EQ(with.drawsCulled, 3u);
    ASSERT_EQ(alone.hdrRgb.size(), crowded.hdrRgb.size());
    EXPECT_TRUE(alone.hdrRgb == crowded.hdrRgb);
}

TEST(Culling, CubeFacesDrawOnlyTheCastersTheySee) {
    // The floor reaches past the light's sides: it lies in the five faces but the one looking
    // up. The box under the light lies in the downward face alone. Six caster draws, not 12.
    RendererStats stats, reference;
    const CapturedFrame culled = floorAndBox(0).render(sharedContext(), {}, &stats);
    EXPECT_EQ(stats.shadowMapsRendered, 1u);
    EXPECT_EQ(stats.shadowCasterDraws, 6u);
    RendererOptions everything;
    everything.culling = false;
    const CapturedFrame drawn = floorAndBox(3).render(sharedContext(), everything, &reference);
    EXPECT_EQ(reference.shadowCasterDraws, 12u);  // the boxes behind are out of reach
    EXPECT_EQ(reference.drawsCulled, 0u);
    EXPECT_TRUE(culled.hdrRgb == drawn.hdrRgb);
}
