// The Atmosphere component (issue 16) in scene files: every field survives a save and a load,
// missing fields take Earth's defaults, and a value outside its domain (negative coefficients,
// a scale height of 0, |g| >= 1, a latitude past the pole, ...) drops the component with an
// error naming the file and the element.
#include <gtest/gtest.h>

#include <span>
#include <string>
#include <vector>

#include "candela/content/component_validation.h"
#include "candela/content/scene_file.h"
#include "scene_component_checks.h"

namespace candela::content {
namespace {

std::optional<SceneDocument> parse(const std::string& text, Diagnostics& diagnostics) {
    return testing::parseScene(text, "sky.scene.json", diagnostics);
}

std::string sceneWithAtmosphere(const std::string& atmosphereJson) {
    return testing::sceneWithComponent("atmosphere", atmosphereJson);
}

TEST(AtmosphereComponent, EveryFieldRoundTripsThroughASceneFile) {
    Atmosphere a;
    a.rayleighScattering = {1e-6f, 2e-6f, 3e-6f};
    a.rayleighScaleHeight = 7000.0f;
    a.mieScattering = 2e-5f;
    a.mieAbsorption = 1e-6f;
    a.mieScaleHeight = 1500.0f;
    a.mieAnisotropy = 0.7f;
    a.ozoneAbsorption = {0.5e-6f, 1.5e-6f, 0.1e-6f};
    a.ozoneCenterHeight = 22000.0f;
    a.ozoneWidth = 20000.0f;
    a.groundRadius = 3.4e6f;
    a.atmosphereHeight = 80000.0f;
    a.groundAlbedo = {0.1f, 0.2f, 0.4f};
    a.solarIlluminance = 100000.0f;
    a.sunAngularDiameter = 1.0f;
    a.latitude = -33.9f;
    a.dayOfYear = 355.0f;
    a.timeOfDay = 17.25f;
    SceneDocument scene;
    scene.entities.emplace_back().atmosphere = a;
    auto loaded = testing::savedAndLoaded(scene, "sky.scene.json");
    ASSERT_TRUE(loaded && loaded->entities.at(0).atmosphere);
    EXPECT_EQ(*loaded->entities[0].atmosphere, a);
}

TEST(AtmosphereComponent, AnEmptyObjectIsEarth) {
    Diagnostics diagnostics;
    auto loaded = parse(sceneWithAtmosphere("{}"), diagnostics);
    ASSERT_TRUE(loaded) << diagnostics.toString();
    ASSERT_TRUE(loaded->entities.at(0).atmosphere);
    EXPECT_EQ(*loaded->entities[0].atmosphere, Atmosphere{});
    EXPECT_FLOAT_EQ(loaded->entities[0].atmosphere->rayleighScattering[2], 33.1e-6f);
}

TEST(AtmosphereComponent, BadValuesAreErrorsNamingTheFileAndTheElement) {
    testing::expectEachComponentIsRejected(
        "sky.scene.json",
        {
            {sceneWithAtmosphere(R"({"rayleighScattering": [1e-6, -1e-6, 0]})"),
             "/entities/0/atmosphere/rayleighScattering", "not negative"},
            {sceneWithAtmosphere(R"({"rayleighScattering": [1e-6, 2e-6]})"),
             "/entities/0/atmosphere/rayleighScattering", "array of 3"},
            {sceneWithAtmosphere(R"({"mieScattering": -1})"),
             "/entities/0/atmosphere/mieScattering", "not negative"},
            {sceneWithAtmosphere(R"({"rayleighScaleHeight": 0})"),
             "/entities/0/atmosphere/rayleighScaleHeight", "positive"},
            {sceneWithAtmosphere(R"({"mieAnisotropy": 1})"), "/entities/0/atmosphere/mieAnisotropy",
             "between -1 and 1"},
            {sceneWithAtmosphere(R"({"groundAlbedo": [0.5, 1.5, 0.5]})"),
             "/entities/0/atmosphere/groundAlbedo", "exceed 1"},
            {sceneWithAtmosphere(R"({"latitude": 91})"), "/entities/0/atmosphere/latitude",
             "[-90, 90]"},
            {sceneWithAtmosphere(R"({"dayOfYear": 0})"), "/entities/0/atmosphere/dayOfYear",
             "[1, 366]"},
            {sceneWithAtmosphere(R"({"timeOfDay": 25})"), "/entities/0/atmosphere/timeOfDay",
             "[0, 24]"},
            {sceneWithAtmosphere(R"({"sunAngularDiameter": 0})"),
             "/entities/0/atmosphere/sunAngularDiameter", "(0, 20]"},
            {sceneWithAtmosphere(R"({"solarIlluminance": "bright"})"),
             "/entities/0/atmosphere/solarIlluminance", "expected a number"},
        },
        [](const SceneEntity& entity) { return entity.atmosphere.has_value(); });
}

TEST(AtmosphereComponent, AbsurdSunIsClampedWithAWarning) {
    Atmosphere a;
    a.solarIlluminance = 1e30f;
    const ValueProblems problems = validateAtmosphere(a);
    EXPECT_FALSE(anyRejected(problems));
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_TRUE(problems[0].clamped);
    EXPECT_EQ(a.solarIlluminance, kMaxLux);
}

// Issue 44: a Rayleigh coefficient of 1e38 overflowed the tables' optical depths and the whole
// frame was NaN. Each coefficient is capped with a warning naming it.
TEST(AtmosphereComponent, AbsurdCoefficientsAreClampedWithAWarning) {
    Atmosphere a;
    a.rayleighScattering = {1e38f, 5.8e-6f, 3e38f};
    a.mieScattering = 1e38f;
    a.mieAbsorption = 1e30f;
    a.ozoneAbsorption = {1e38f, 0.0f, 0.0f};
    const ValueProblems problems = validateAtmosphere(a);
    EXPECT_FALSE(anyRejected(problems));
    std::vector<std::string> fields;
    for (const ValueProblem& p : problems) {
        EXPECT_TRUE(p.clamped) << p.field;
        fields.push_back(p.field);
    }
    EXPECT_EQ(fields, (std::vector<std::string>{"rayleighScattering", "ozoneAbsorption",
                                                "mieScattering", "mieAbsorption"}));
    EXPECT_EQ(a.rayleighScattering[0], kMaxAirCoefficient);
    EXPECT_EQ(a.rayleighScattering[1], 5.8e-6f);
    EXPECT_EQ(a.rayleighScattering[2], kMaxAirCoefficient);
    EXPECT_EQ(a.mieScattering, kMaxAirCoefficient);
    EXPECT_EQ(a.mieAbsorption, kMaxAirCoefficient);
    EXPECT_EQ(a.ozoneAbsorption[0], kMaxAirCoefficient);
}

}  // namespace
}  // namespace candela::content
