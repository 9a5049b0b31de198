// The atmosphere's sun in a frame (issue 16): where the time of day puts it, and the scene's
// first directional light turned into it (direction kept or placed, lux and colour from the
// transmittance), or one added when the scene has none.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/constants.hpp>

#include "candela/render/atmosphere_transmittance.h"
#include "candela/runtime/atmosphere_sun.h"

namespace candela::runtime {
namespace {

TEST(AtmosphereSunLight, TimeOfDayPlacesTheSun) {
    // The equator at an equinox: overhead at noon, rising due east (+X) at six.
    const float equinox = 80.0f;
    EXPECT_NEAR(sunDirectionAtTime(0.0f, equinox, 12.0f).y, 1.0f, 1e-3f);
    const glm::vec3 dawn = sunDirectionAtTime(0.0f, equinox, 6.0f);
    EXPECT_NEAR(dawn.x, 1.0f, 1e-2f);
    EXPECT_NEAR(dawn.y, 0.0f, 1e-2f);
    // 45 degrees north at the June solstice: noon 68.4 degrees up, due south (+Z).
    const glm::vec3 noon = sunDirectionAtTime(45.0f, 172.0f, 12.0f);
    EXPECT_NEAR(glm::degrees(std::asin(noon.y)), 90.0f - 45.0f + 23.44f, 0.1f);
    EXPECT_NEAR(noon.x, 0.0f, 1e-4f);
    EXPECT_GT(noon.z, 0.0f);
    // The afternoon sun is in the west (-X); midnight's is below the horizon.
    EXPECT_LT(sunDirectionAtTime(45.0f, 172.0f, 16.0f).x, 0.0f);
    EXPECT_LT(sunDirectionAtTime(45.0f, 172.0f, 0.0f).y, 0.0f);
}

TEST(AtmosphereSunLight, FirstDirectionalLightBecomesTheSun) {
    render::LightInstance lamp;
    lamp.light.type = content::LightType::Point;
    render::LightInstance sun;
    sun.light.type = content::LightType::Directional;
    sun.light.lux = 5.0f;
    // It travels north: the sun stands 45 degrees up in the south.
    sun.direction = glm::normalize(glm::vec3(0.0f, -1.0f, -1.0f));
    std::vector<render::LightInstance> lights = {lamp, sun};
    render::FrameScene scene;
    scene.lights = lights;
    scene.atmosphere = content::Atmosphere{};
    scene.lightsRestructured = false;
    AtmosphereSun atmosphereSun;
    atmosphereSun.apply({}, scene);
    ASSERT_EQ(scene.lights.size(), 2u);
    const render::LightInstance& lit = scene.lights[1];
    EXPECT_NEAR(glm::dot(lit.direction, sun.direction), 1.0f, 1e-5f) << "direction kept";
    const glm::dvec3 e =
        render::sunIlluminanceAtGround(content::Atmosphere{}, 0.0, std::sin(glm::pi<double>() / 4));
    EXPECT_NEAR(lit.light.lux, render::luminanceOf(e), 1.0);
    EXPECT_GT(lit.light.color[0], lit.light.color[2]) << "dimmer in blue than in red";
    EXPECT_EQ(scene.changedLights.back(), 1u);

    atmosphereSun.apply({10.0f, std::nullopt}, scene);
    EXPECT_NEAR(glm::degrees(std::asin(-scene.lights[1].direction.y)), 10.0f, 1e-3f);
    EXPECT_LT(scene.lights[1].direction.z, 0.0f) << "the same azimuth";
}

TEST(AtmosphereSunLight, SceneWithoutADirectionalLightGetsOne) {
    render::FrameScene scene;
    scene.atmosphere = content::Atmosphere{};
    AtmosphereSun atmosphereSun;
    atmosphereSun.apply({30.0f, std::nullopt}, scene);
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.lights[0].light.type, content::LightType::Directional);
    EXPECT_TRUE(scene.lights[0].light.castShadows);
    EXPECT_GT(scene.lights[0].light.lux, 50000.0f);
    EXPECT_TRUE(scene.lightsRestructured);
}

}  // namespace
}  // namespace candela::runtime
