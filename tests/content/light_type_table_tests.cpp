// The content side's light type table (content/light_types.h) drives the scene reader and
// writer and validateLight: every type and every field it lists must survive a scene file and
// be checked under its own name.
#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <span>
#include <string>

#include "candela/content/component_validation.h"
#include "candela/content/light_types.h"
#include "candela/content/scene_file.h"

namespace candela::content {
namespace {

// A valid value for each field that differs from its default.
float distinctValue(const LightFieldInfo& f) {
    if (f.field == LightField::InnerConeAngle) return 0.3f;
    if (f.field == LightField::OuterConeAngle) return 0.7f;
    return 0.25f + 0.5f * float(f.field);
}

TEST(LightTypeTable, EveryTypeAndFieldRoundTripsThroughASceneFile) {
    for (const LightTypeInfo& type : kLightTypeTable) {
        SCOPED_TRACE(type.name);
        Light light;
        light.type = type.type;
        for (const LightFieldInfo& f : kLightFieldTable) {
            if (f.channels) {
                light.*f.channels = {0.2f, 0.4f, 0.6f};
            } else {
                light.*f.scalar = distinctValue(f);
            }
        }
        SceneDocument scene;
        scene.entities.emplace_back().light = light;
        std::string error;
        const std::string text = sceneToJson(scene, error);
        ASSERT_EQ(error, "");
        EXPECT_NE(text.find('"' + std::string(type.name) + '"'), std::string::npos) << text;

        Diagnostics diagnostics;
        auto loaded =
            parseSceneJson(std::as_bytes(std::span(text)), "lights.scene.json", diagnostics);
        ASSERT_TRUE(loaded) << diagnostics.toString();
        EXPECT_TRUE(diagnostics.messages.empty()) << diagnostics.toString();
        ASSERT_EQ(loaded->entities.size(), 1u);
        ASSERT_TRUE(loaded->entities[0].light);
        const Light& back = *loaded->entities[0].light;
        EXPECT_EQ(back.type, type.type);
        for (const LightFieldInfo& f : kLightFieldTable) {
            SCOPED_TRACE(f.name);
            if (f.channels) {
                EXPECT_EQ(std::memcmp((back.*f.channels).data(), (light.*f.channels).data(), 12),
                          0);
            } else {
                EXPECT_EQ(back.*f.scalar, light.*f.scalar);
            }
        }
    }
}

// castShadows: written and read back either way; absent, each type's default (directional
// lights cast, point and spot lights do not); not a boolean, an error naming the key.
TEST(LightTypeTable, CastShadowsRoundTripsAndDefaultsPerType) {
    for (const LightTypeInfo& type : kLightTypeTable) {
        SCOPED_TRACE(type.name);
        for (bool cast : {false, true}) {
            SceneDocument scene;
            Light light;
            light.type = type.type;
            light.castShadows = cast;
            light.sourceRadius = 0.5f;  // a disk light needs an area
            scene.entities.emplace_back().light = light;
            std::string error;
            const std::string text = sceneToJson(scene, error);
            ASSERT_EQ(error, "");
            Diagnostics diagnostics;
            auto loaded =
                parseSceneJson(std::as_bytes(std::span(text)), "cast.scene.json", diagnostics);
            ASSERT_TRUE(loaded) << diagnostics.toString();
            EXPECT_EQ(loaded->entities[0].light->castShadows, cast);
        }
        const std::string absent = std::string(R"({"format": "candela.scene", "version": 1,
            "entities": [{"name": "l", "light": {"type": ")") +
                                   type.name + R"(", "sourceRadius": 0.5}}]})";
        Diagnostics diagnostics;
        auto loaded =
            parseSceneJson(std::as_bytes(std::span(absent)), "default.scene.json", diagnostics);
        ASSERT_TRUE(loaded) << diagnostics.toString();
        EXPECT_EQ(loaded->entities[0].light->castShadows, type.castsShadowsByDefault);
    }
    EXPECT_TRUE(lightTypeInfo(LightType::Directional).castsShadowsByDefault);
    EXPECT_FALSE(lightTypeInfo(LightType::Point).castsShadowsByDefault);
    EXPECT_FALSE(lightTypeInfo(LightType::Spot).castsShadowsByDefault);
    const std::string wrong = R"({"format": "candela.scene", "version": 1,
        "entities": [{"name": "l", "light": {"type": "point", "castShadows": 1}}]})";
    Diagnostics diagnostics;
    parseSceneJson(std::as_bytes(std::span(wrong)), "wrong.scene.json", diagnostics);
    EXPECT_TRUE(diagnostics.mentions("castShadows")) << diagnostics.toString();
}

bool rejects(const ValueProblems& problems, const std::string& field) {
    for (const ValueProblem& p : problems) {
        if (!p.clamped && p.field == field) return true;
    }
    return false;
}

TEST(LightTypeTable, ValidateLightChecksEveryFieldUnderItsName) {
    for (const LightFieldInfo& f : kLightFieldTable) {
        SCOPED_TRACE(f.name);
        Light light;
        // Cones are checked for the types that use them only.
        light.type = f.rule == LightFieldRule::ConeAngle ? LightType::Spot : LightType::Point;
        if (f.channels) {
            (light.*f.channels)[1] = -1.0f;
        } else {
            light.*f.scalar = -1.0f;
        }
        EXPECT_TRUE(rejects(validateLight(light), f.name));
    }
    for (const LightTypeInfo& type : kLightTypeTable) {
        SCOPED_TRACE(type.name);
        Light light;
        light.type = type.type;
        light.outerConeAngle = -1.0f;
        EXPECT_EQ(rejects(validateLight(light), "outerConeAngle"),
                  usesField(type.type, LightField::OuterConeAngle));
    }
}

TEST(LightTypeTable, PowerFieldMatchesTheTypesPhotometricQuantity) {
    for (const LightTypeInfo& type : kLightTypeTable) {
        SCOPED_TRACE(type.name);
        const LightField power =
            type.power == LightPower::Lux ? LightField::Lux : LightField::Lumens;
        EXPECT_TRUE(usesField(type.type, power));
        EXPECT_TRUE(usesField(type.type, LightField::Color));
    }
}

// Area lights (issue 15): a negative or zero size, a zero-area disk or a non-finite size is an
// error naming the file and the element, and the light is skipped; a good one loads with its
// per-light "quality".
TEST(LightTypeTable, AreaLightsWithoutAnAreaAreRejectedByName) {
    const std::string text = R"({"format": "candela.scene", "version": 1, "entities": [
        {"name": "negative", "light": {"type": "rect", "width": -1, "height": 0.5}},
        {"name": "flat", "light": {"type": "rect", "width": 1, "height": 0}},
        {"name": "dot", "light": {"type": "disk", "sourceRadius": 0}},
        {"name": "good", "light": {"type": "disk", "sourceRadius": 0.3, "lumens": 2000,
                                   "quality": "representative"}}]})";
    Diagnostics diagnostics;
    auto loaded = parseSceneJson(std::as_bytes(std::span(text)), "area.scene.json", diagnostics);
    ASSERT_TRUE(loaded) << diagnostics.toString();
    ASSERT_EQ(loaded->entities.size(), 4u);
    for (int i = 0; i < 3; ++i)
        EXPECT_FALSE(loaded->entities[size_t(i)].light) << i;
    ASSERT_TRUE(loaded->entities[3].light);
    EXPECT_EQ(loaded->entities[3].light->quality, AreaLightQuality::Representative);
    const std::string messages = diagnostics.toString();
    EXPECT_NE(messages.find("area.scene.json"), std::string::npos) << messages;
    EXPECT_NE(messages.find("/entities/0/light/width"), std::string::npos) << messages;
    EXPECT_NE(messages.find("/entities/1/light/height"), std::string::npos) << messages;
    EXPECT_NE(messages.find("/entities/2/light/sourceRadius"), std::string::npos) << messages;

    Light nan;
    nan.type = LightType::Rect;
    nan.width = std::numeric_limits<float>::quiet_NaN();
    EXPECT_TRUE(rejects(validateLight(nan), "width"));
    Light disk;
    disk.type = LightType::Disk;
    EXPECT_TRUE(rejects(validateLight(disk), "sourceRadius"));  // default radius 0: no area
    disk.sourceRadius = 0.2f;
    EXPECT_TRUE(validateLight(disk).empty());
    EXPECT_NEAR(emitterArea(disk), 3.14159265f * 0.04f, 1e-6f);
}

// Issue 44: area, sphere and tube lights switched off without a word at extreme accepted sizes
// (a disk of radius 1e-45 or 1e20, a 1e-30 m rect, a sphere radius or tube length of 3e38).
// Too small an emitter is clamped up to kMinAreaLightSize, too large a one down to
// kMaxAreaLightSize, each with a warning naming the field; Inf and NaN stay errors.
TEST(LightTypeTable, ExtremeEmitterSizesAreClampedWithAWarning) {
    struct Case {
        LightType type;
        float Light::*field;
        const char* name;
        float value;
        float expected;
    };
    const float tiny = std::numeric_limits<float>::denorm_min();
    const Case cases[] = {
        {LightType::Disk, &Light::sourceRadius, "sourceRadius", tiny, kMinAreaLightSize},
        {LightType::Disk, &Light::sourceRadius, "sourceRadius", 1e20f, kMaxAreaLightSize},
        {LightType::Rect, &Light::width, "width", 1e-30f, kMinAreaLightSize},
        {LightType::Rect, &Light::height, "height", 5e-4f, kMinAreaLightSize},
        {LightType::Point, &Light::sourceRadius, "sourceRadius", 3e38f, kMaxAreaLightSize},
        {LightType::Point, &Light::sourceLength, "sourceLength", 3e38f, kMaxAreaLightSize},
        {LightType::Spot, &Light::sourceRadius, "sourceRadius", 1e5f, kMaxAreaLightSize},
    };
    for (const Case& c : cases) {
        Light light;
        light.type = c.type;
        if (c.type == LightType::Disk) light.sourceRadius = 0.2f;
        light.*c.field = c.value;
        const ValueProblems problems = validateLight(light);
        ASSERT_EQ(problems.size(), 1u) << c.name << " " << c.value;
        EXPECT_EQ(problems[0].field, c.name);
        EXPECT_TRUE(problems[0].clamped) << problems[0].message;
        EXPECT_EQ(light.*c.field, c.expected) << c.name << " " << c.value;
    }
    // A point light's sphere may be as small as it likes: it is a point light then.
    Light point;
    point.sourceRadius = tiny;
    EXPECT_TRUE(validateLight(point).empty());
    Light infinite;
    infinite.sourceLength = std::numeric_limits<float>::infinity();
    EXPECT_TRUE(rejects(validateLight(infinite), "sourceLength"));
}

// Drobot's (2014, GPU Pro 5, "Physically Based Area Lights") constant-intensity variant: a rect's
// or disk's "emission" loads, is written back (and left out when Lambertian), and a misspelt value
// is an error naming its pointer.
TEST(LightTypeTable, AreaLightEmissionRoundTripsAndRejectsUnknownValues) {
    const std::string text = R"({"format": "candela.scene", "version": 1, "entities": [
        {"name": "panel", "light": {"type": "rect", "width": 1, "height": 0.5,
                                    "emission": "constantIntensity"}},
        {"name": "plain", "light": {"type": "disk", "sourceRadius": 0.3}},
        {"name": "typo", "light": {"type": "disk", "sourceRadius": 0.3,
                                   "emission": "isotropic"}}]})";
    Diagnostics diagnostics;
    auto loaded = parseSceneJson(std::as_bytes(std::span(text)), "emit.scene.json", diagnostics);
    ASSERT_TRUE(loaded) << diagnostics.toString();
    ASSERT_EQ(loaded->entities.size(), 3u);
    ASSERT_TRUE(loaded->entities[0].light && loaded->entities[1].light);
    EXPECT_EQ(loaded->entities[0].light->emission, AreaLightEmission::ConstantIntensity);
    EXPECT_EQ(loaded->entities[1].light->emission, AreaLightEmission::Lambertian);
    const std::string messages = diagnostics.toString();
    EXPECT_NE(messages.find("/entities/2/light/emission"), std::string::npos) << messages;

    loaded->entities.pop_back();
    std::string error;
    const std::string json = sceneToJson(*loaded, error);
    ASSERT_TRUE(error.empty()) << error;
    EXPECT_NE(json.find("\"emission\": \"constantIntensity\""), std::string::npos) << json;
    EXPECT_EQ(json.find("lambertian"), std::string::npos) << json;
}

}  // namespace
}  // namespace candela::content
