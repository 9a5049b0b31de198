// AudioSource and AudioListener (issue 47) in scene files: the interface form reads as
// written, every field survives a save and a load, the clip is resolved against the scene file
// when instantiated and saved relative to wherever the scene is saved, and absurd values are
// clamped with a warning.
#include <gtest/gtest.h>

#include <string>

#include "candela/content/asset_cache.h"
#include "candela/content/component_validation.h"
#include "candela/content/scene_file.h"
#include "candela/content/scene_instantiation.h"
#include "scene_component_checks.h"

namespace candela::content {
namespace {

constexpr const char* kFile = "audio.scene.json";

TEST(AudioComponents, TheIssueFormReadsAsWritten) {
    Diagnostics diagnostics;
    auto loaded = testing::parseScene(
        testing::sceneWithComponent(
            "audioSource",
            R"({"clip": "sounds/tone.wav", "loop": true, "gain": 1.0, "spatial": true})",
            R"("audioListener": {}, )"),
        kFile, diagnostics);
    ASSERT_TRUE(loaded) << diagnostics.toString();
    EXPECT_TRUE(diagnostics.messages.empty()) << diagnostics.toString();
    const SceneEntity& e = loaded->entities.at(0);
    ASSERT_TRUE(e.audioSource && e.audioListener);
    EXPECT_EQ(e.audioSource->clip, "sounds/tone.wav");
    EXPECT_TRUE(e.audioSource->loop);
    EXPECT_TRUE(e.audioSource->spatial);
    EXPECT_EQ(e.audioSource->gain, 1.0f);
    EXPECT_EQ(e.audioSource->state, PlaybackState::Playing);
    EXPECT_EQ(e.audioListener->gain, 1.0f);
}

TEST(AudioComponents, EveryFieldRoundTripsThroughASceneFile) {
    AudioSource source;
    source.clip = "music/theme.ogg";
    source.gain = 0.25f;
    source.pitch = 1.5f;
    source.loop = true;
    source.spatial = false;
    source.minDistance = 2.0f;
    source.maxDistance = 40.0f;
    source.rolloff = 0.5f;
    source.state = PlaybackState::Stopped;  // "playing": false: waits for play()
    AudioListener listener;
    listener.gain = 0.75f;
    SceneDocument scene;
    scene.entities.emplace_back().audioSource = source;
    scene.entities.back().audioListener = listener;
    auto loaded = testing::savedAndLoaded(scene, kFile);
    ASSERT_TRUE(loaded);
    EXPECT_EQ(loaded->entities.at(0).audioSource, source);
    EXPECT_EQ(loaded->entities.at(0).audioListener, listener);
}

TEST(AudioComponents, TheClipResolvesAgainstTheSceneAndSavesRelativeToWhereItIsSaved) {
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / "candela-audio-scene";
    std::filesystem::create_directories(dir / "levels" / "copies");
    SceneDocument scene;
    scene.entities.emplace_back().audioSource = AudioSource{.clip = "../sounds/tone.wav"};
    ecs::Registry registry;
    AssetCache cache;
    Diagnostics diagnostics;
    instantiateScene(registry, scene, dir / "levels" / "a.scene.json", cache, diagnostics);
    std::string clip;
    registry.view<AudioSource>().each([&](const AudioSource& a) { clip = a.clip; });
    EXPECT_EQ(clip, (dir / "sounds" / "tone.wav").string()) << "absolute, resolved";
    const SceneDocument captured = captureScene(registry);
    ASSERT_EQ(saveSceneFile(dir / "levels" / "copies" / "b.scene.json", captured), "");
    auto saved = loadSceneFile(dir / "levels" / "copies" / "b.scene.json", diagnostics);
    ASSERT_TRUE(saved && saved->entities.at(0).audioSource) << diagnostics.toString();
    EXPECT_EQ(saved->entities[0].audioSource->clip, "../../sounds/tone.wav");
    std::filesystem::remove_all(dir);
}

TEST(AudioComponents, AbsurdValuesAreClampedWithAWarning) {
    Diagnostics diagnostics;
    auto loaded = testing::parseScene(
        testing::sceneWithComponent(
            "audioSource",
            R"({"clip": "a.wav", "gain": -2, "pitch": 1e9, "minDistance": 0, "maxDistance": 1e-9, "rolloff": -1})"),
        kFile, diagnostics);
    ASSERT_TRUE(loaded && loaded->entities.at(0).audioSource) << diagnostics.toString();
    const AudioSource& a = *loaded->entities[0].audioSource;
    EXPECT_EQ(a.gain, 0.0f);
    EXPECT_EQ(a.pitch, kMaxAudioPitch);
    EXPECT_EQ(a.minDistance, kMinAudioDistance);
    EXPECT_EQ(a.maxDistance, a.minDistance);
    EXPECT_EQ(a.rolloff, 0.0f);
    const std::string text = diagnostics.toString();
    for (const char* field : {"gain", "pitch", "minDistance", "maxDistance", "rolloff"})
        EXPECT_NE(text.find(std::string("/entities/0/audioSource/") + field), std::string::npos)
            << text;
    EXPECT_EQ(diagnostics.count(Severity::Error), 0u) << text;
}

TEST(AudioComponents, ASourceWithoutAClipIsAnErrorNamingTheElement) {
    const auto source = [](const std::string& json) {
        return testing::sceneWithComponent("audioSource", json);
    };
    testing::expectEachComponentIsRejected(
        kFile,
        {
            {source(R"({"loop": true})"), "/entities/0/audioSource/clip", "clip"},
            {source(R"({"clip": ""})"), "/entities/0/audioSource/clip", "empty"},
            {source(R"({"clip": 3})"), "/entities/0/audioSource/clip", "string"},
            {source(R"({"clip": "a.wav", "loop": "yes"})"), "/entities/0/audioSource/loop",
             "true or false"},
        },
        [](const SceneEntity& e) { return e.audioSource.has_value(); });
}

}  // namespace
}  // namespace candela::content
