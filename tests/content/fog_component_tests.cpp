// The Fog component (issue 17) in scene files: every field survives a save and a load, and a
// value outside the medium's domain (negative coefficients, |g| >= 1, a negative height
// falloff, a box whose min is not below its max) drops the component with an error naming the file
// and the element.
#include <gtest/gtest.h>

#include <span>
#include <string>

#include "candela/content/component_validation.h"
#include "candela/content/scene_file.h"
#include "scene_component_checks.h"

namespace candela::content {
namespace {

std::optional<SceneDocument> parse(const std::string& text, Diagnostics& diagnostics) {
    return testing::parseScene(text, "fog.scene.json", diagnostics);
}

std::string sceneWithFog(const std::string& fogJson) {
    return testing::sceneWithComponent("fog", fogJson);
}

TEST(FogComponent, EveryFieldRoundTripsThroughASceneFile) {
    Fog fog;
    fog.scattering = 0.125f;
    fog.absorption = 0.0375f;
    fog.anisotropy = -0.6f;
    fog.heightFalloff = 0.3f;
    fog.baseHeight = -1.5f;
    fog.bounds = FogBounds{{-6.5f, 0.0f, -9.5f}, {6.5f, 5.25f, 8.0f}};
    SceneDocument scene;
    scene.entities.emplace_back().fog = fog;
    auto loaded = testing::savedAndLoaded(scene, "fog.scene.json");
    ASSERT_TRUE(loaded && loaded->entities.at(0).fog);
    EXPECT_EQ(*loaded->entities[0].fog, fog);
}

TEST(FogComponent, MissingFieldsTakeTheDefaults) {
    Diagnostics diagnostics;
    auto loaded = parse(sceneWithFog(R"({"scattering": 0.05})"), diagnostics);
    ASSERT_TRUE(loaded) << diagnostics.toString();
    ASSERT_TRUE(loaded->entities.at(0).fog);
    Fog expected;
    expected.scattering = 0.05f;
    EXPECT_EQ(*loaded->entities[0].fog, expected);
}

TEST(FogComponent, BadValuesAreErrorsNamingTheFileAndTheElement) {
    testing::expectEachComponentIsRejected(
        "fog.scene.json",
        {
            {sceneWithFog(R"({"scattering": -0.1})"), "/entities/0/fog/scattering", "negative"},
            {sceneWithFog(R"({"absorption": -2})"), "/entities/0/fog/absorption", "negative"},
            {sceneWithFog(R"({"anisotropy": 1})"), "/entities/0/fog/anisotropy",
             "between -1 and 1"},
            {sceneWithFog(R"({"anisotropy": -1.5})"), "/entities/0/fog/anisotropy",
             "between -1 and 1"},
            {sceneWithFog(R"({"heightFalloff": -0.5})"), "/entities/0/fog/heightFalloff",
             "negative"},
            {sceneWithFog(R"({"scattering": "thick"})"), "/entities/0/fog/scattering",
             "expected a number"},
            {sceneWithFog(R"({"bounds": {"min": [0, 0, 0], "max": [1, -1, 1]}})"),
             "/entities/0/fog/bounds", "min must be below max"},
            {sceneWithFog(R"({"bounds": {"min": [0, 0], "max": [1, 1, 1]}})"),
             "/entities/0/fog/bounds/min", "array of 3 numbers"},
            {sceneWithFog(R"({"bounds": {"min": [0, 0, 0]}})"), "/entities/0/fog/bounds/max",
             "array of 3 numbers"},
            {sceneWithFog(R"({"bounds": [0, 0, 0]})"), "/entities/0/fog/bounds",
             "expected an object"},
        },
        [](const SceneEntity& entity) { return entity.fog.has_value(); });
}

TEST(FogComponent, AbsurdCoefficientsAreClampedWithAWarning) {
    Fog fog;
    fog.scattering = 1e9f;
    const ValueProblems problems = validateFog(fog);
    EXPECT_FALSE(anyRejected(problems));
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_TRUE(problems[0].clamped);
    EXPECT_EQ(fog.scattering, kMaxFogCoefficient);
}

TEST(FogComponent, ALightsVolumetricScaleRoundTripsAndRejectsNegatives) {
    Diagnostics diagnostics;
    auto loaded = parse(
        R"({"format": "candela.scene", "version": 1, "entities": [{"name": "a", "light": {"type": "point", "volumetric": 2.5}},
            {"name": "b", "light": {"type": "point", "volumetric": -1}},
            {"name": "c", "light": {"type": "spot"}}]})",
        diagnostics);
    ASSERT_TRUE(loaded);
    ASSERT_TRUE(loaded->entities.at(0).light);
    EXPECT_EQ(loaded->entities[0].light->volumetric, 2.5f);
    EXPECT_FALSE(loaded->entities.at(1).light);
    EXPECT_NE(diagnostics.toString().find("/entities/1/light/volumetric"), std::string::npos)
        << diagnostics.toString();
    ASSERT_TRUE(loaded->entities.at(2).light);
    EXPECT_EQ(loaded->entities[2].light->volumetric, 1.0f) << "1 when the file does not say";
}

}  // namespace
}  // namespace candela::content
