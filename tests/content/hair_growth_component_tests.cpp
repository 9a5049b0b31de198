// Hair grown on a mesh (issue 19) in scene files: every field of an entity's "hair" block
// survives a save and a load, and a bad value (no mesh beside it, a zero count or length, a
// radius not above 0, a colour out of [0, 1]) drops the block with an error naming the file
// and the element.
#include <gtest/gtest.h>

#include <span>
#include <string>

#include "candela/content/scene_file.h"
#include "scene_component_checks.h"

namespace candela::content {
namespace {

std::string sceneWithHair(const std::string& hairJson, bool mesh = true) {
    return testing::sceneWithComponent("hair", hairJson,
                                       mesh ? R"("mesh": {"gltf": "cat.gltf", "mesh": 0}, )" : "");
}

TEST(HairGrowthComponent, EveryFieldRoundTripsThroughASceneFile) {
    HairGrowth hair;
    hair.count = 1234;
    hair.length = 0.075f;
    hair.seed = 42;
    hair.style.rootRadius = 0.002f;
    hair.style.tipRadius = 0.0005f;
    hair.style.color = {0.5f, 0.25f, 0.125f};
    hair.style.primaryShift = 0.2f;
    hair.style.secondaryShift = -0.15f;
    hair.style.primaryExponent = 64.0f;
    hair.style.secondaryExponent = 16.0f;
    SceneDocument scene;
    SceneEntity& entity = scene.entities.emplace_back();
    entity.mesh = MeshReference{"cat.gltf", 0, ""};
    entity.hair = hair;
    auto loaded = testing::savedAndLoaded(scene, "fur.scene.json");
    ASSERT_TRUE(loaded && loaded->entities.at(0).hair);
    EXPECT_EQ(*loaded->entities[0].hair, hair);
}

TEST(HairGrowthComponent, BadValuesAreErrorsNamingTheFileAndTheElement) {
    testing::expectEachComponentIsRejected(
        "fur.scene.json",
        {
            {sceneWithHair(R"({"count": 10})", false), "/entities/0/hair"},
            {sceneWithHair(R"({"count": 0})"), "/entities/0/hair/count"},
            {sceneWithHair(R"({"length": 0})"), "/entities/0/hair/length"},
            {sceneWithHair(R"({"style": {"rootRadius": -1}})"),
             "/entities/0/hair/style/rootRadius"},
            {sceneWithHair(R"({"style": {"color": [0, 2, 0]}})"), "/entities/0/hair/style/color"},
            {sceneWithHair(R"({"style": {"secondaryExponent": "soft"}})"),
             "/entities/0/hair/style/secondaryExponent"},
        },
        [](const SceneEntity& entity) { return entity.hair.has_value(); });
}

}  // namespace
}  // namespace candela::content
