// Scene files keep an instantiated glTF model and its AnimationPlayer's state: loading
// restores clip, time, speed, loop and a crossfade in progress; saving writes them back; bad
// values are named (file and element) and the model still loads with its player reset.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "candela/content/animation_systems.h"
#include "candela/content/components/animation.h"
#include "candela/content/components/scene_components.h"
#include "candela/content/scene_file.h"
#include "candela/content/scene_instantiation.h"
#include "candela/ecs/hierarchy.h"
#include "candela/ecs/transform_propagation.h"
#include "test_paths.h"

namespace candela::content {
namespace {

std::string foxPath() {
    return (std::filesystem::path(CANDELA_SHARED_ASSETS) / "models/Fox/Fox.glb").string();
}

void writeText(const std::filesystem::path& path, const std::string& text) {
    std::ofstream(path) << text;
}

// A scene loaded into its own registry, with the animation systems' frame.
struct LoadedScene {
    ecs::Registry registry;
    ecs::JobSystem jobs{1};
    AssetCache cache;
    Diagnostics diagnostics;
    std::vector<ecs::Entity> entities;

    bool load(const std::filesystem::path& path) {
        auto scene = loadSceneFile(path, diagnostics);
        if (!scene) return false;
        entities = instantiateScene(registry, *scene, path, cache, diagnostics);
        return true;
    }
    void frame(float seconds) {
        advanceAnimationPlayers(registry, jobs, seconds);
        ecs::propagateTransforms(registry);
        updateSkins(registry, jobs);
    }
    AnimationPlayer* player(std::size_t entity) {
        return registry.tryGet<AnimationPlayer>(entities.at(entity));
    }
};

std::string foxEntity(const std::string& name, const std::string& animation) {
    return R"({"name": ")" + name + R"(", "model": {"gltf": ")" + foxPath() + R"("})" +
           (animation.empty() ? "" : R"(, "animation": )" + animation) + "}";
}

std::string sceneText(const std::vector<std::string>& entities) {
    std::string text = R"({"format": "candela.scene", "version": 1, "entities": [)";
    for (std::size_t i = 0; i < entities.size(); ++i)
        text += (i ? ", " : "") + entities[i];
    return text + "]}";
}

TEST(SceneAnimation, LoadAdvanceSaveLoadKeepsThePlayerStateAndThePose) {
    const auto first = testing::tempPath("fox.scene.json");
    writeText(
        first,
        sceneText({foxEntity("fox", R"({"clip": "Walk", "time": 0.25, "speed": 1.5, "loop": true,
                                    "crossfade": {"clip": "Run", "time": 0.1, "duration": 1.0,
                                                  "elapsed": 0.2}})")}));
    LoadedScene a;
    ASSERT_TRUE(a.load(first));
    EXPECT_FALSE(a.diagnostics.hasErrors()) << a.diagnostics.toString();
    AnimationPlayer* pa = a.player(0);
    ASSERT_NE(pa, nullptr) << "the player sits on the scene entity";
    EXPECT_EQ(pa->clip, pa->findClip("Walk"));
    EXPECT_EQ(pa->nextClip, pa->findClip("Run"));
    EXPECT_FLOAT_EQ(pa->time, 0.25f);
    EXPECT_FLOAT_EQ(pa->speed, 1.5f);
    EXPECT_FLOAT_EQ(pa->fadeElapsed, 0.2f);
    EXPECT_GT(ecs::childrenOf(a.registry, a.entities[0]).size(), 0u)
        << "the glTF's nodes sit under it";

    a.frame(0.1f);
    a.frame(0.15f);  // the fade is mid-way: 0.2 + 1.5 * 0.25 of 1 s
    ASSERT_EQ(pa->nextClip, pa->findClip("Run")) << "still crossfading";
    const auto second = testing::tempPath("saved.scene.json");
    ASSERT_EQ(saveSceneFile(second, captureScene(a.registry)), "");

    LoadedScene b;
    ASSERT_TRUE(b.load(second));
    EXPECT_FALSE(b.diagnostics.hasErrors()) << b.diagnostics.toString();
    AnimationPlayer* pb = b.player(0);
    ASSERT_NE(pb, nullptr);
    EXPECT_EQ(pb->clip, pa->clip);
    EXPECT_EQ(pb->nextClip, pa->nextClip);
    EXPECT_EQ(pb->time, pa->time);
    EXPECT_EQ(pb->nextTime, pa->nextTime);
    EXPECT_EQ(pb->speed, pa->speed);
    EXPECT_EQ(pb->loop, pa->loop);
    EXPECT_EQ(pb->playing, pa->playing);
    EXPECT_EQ(pb->fadeDuration, pa->fadeDuration);
    EXPECT_EQ(pb->fadeElapsed, pa->fadeElapsed);

    // Both pose their nodes at the same instant: every animated node matches bit for bit.
    a.frame(0.0f);
    b.frame(0.0f);
    ASSERT_EQ(pa->nodeEntities.size(), pb->nodeEntities.size());
    std::size_t compared = 0;
    for (std::size_t n = 0; n < pa->nodeEntities.size(); ++n) {
        if (pa->nodeEntities[n] == ecs::kNullEntity) continue;
        const auto& la = a.registry.get<ecs::LocalTransform>(pa->nodeEntities[n]);
        const auto& lb = b.registry.get<ecs::LocalTransform>(pb->nodeEntities[n]);
        EXPECT_EQ(std::memcmp(&la, &lb, sizeof la), 0) << "node " << n;
        ++compared;
    }
    EXPECT_GT(compared, 20u);

    // And saving the reloaded scene writes the same file.
    const auto third = testing::tempPath("again.scene.json");
    ASSERT_EQ(saveSceneFile(third, captureScene(b.registry)), "");
    auto read = [](const std::filesystem::path& p) {
        std::ifstream in(p);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    EXPECT_EQ(read(second), read(third));
    EXPECT_NE(read(second).find(R"("clip": "Run")"), std::string::npos) << read(second);
}

TEST(SceneAnimation, BadValuesAreNamedAndTheModelLoadsWithItsPlayerReset) {
    const auto path = testing::tempPath("bad.scene.json");
    writeText(path, sceneText({
                        foxEntity("unknown clip", R"({"clip": "Gallop", "time": 0.5})"),
                        foxEntity("nan time", R"({"clip": "Run", "time": "NaN"})"),
                        foxEntity("negative fade", R"({"clip": 1, "crossfade":
                                                   {"clip": 2, "duration": -1}})"),
                        foxEntity("clip out of range", R"({"clip": 7})"),
                    }));
    LoadedScene scene;
    ASSERT_TRUE(scene.load(path));
    const std::string messages = scene.diagnostics.toString();
    EXPECT_TRUE(scene.diagnostics.mentions("no clip named 'Gallop'")) << messages;
    EXPECT_TRUE(scene.diagnostics.mentions("no clip 7")) << messages;
    std::size_t named = 0;
    for (const Diagnostic& d : scene.diagnostics.messages) {
        EXPECT_EQ(d.file, path.string());
        named += d.element == "/entities/0/animation/clip" ||
                 d.element == "/entities/1/animation/time" ||
                 d.element == "/entities/2/animation/crossfade/duration" ||
                 d.element == "/entities/3/animation/clip";
    }
    EXPECT_EQ(named, 4u) << messages;
    for (std::size_t i = 0; i < 4; ++i) {
        AnimationPlayer* player = scene.player(i);
        ASSERT_NE(player, nullptr) << "entity " << i << " still has its model and player";
        EXPECT_EQ(player->clip, 0) << "reset to the first clip";
        EXPECT_EQ(player->time, 0.0f);
        EXPECT_EQ(player->nextClip, -1);
        EXPECT_TRUE(player->loop);
        EXPECT_GT(ecs::childrenOf(scene.registry, scene.entities[i]).size(), 0u);
    }
}

}  // namespace
}  // namespace candela::content
