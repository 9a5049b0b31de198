// Playing, looping, pausing and streaming through the component, and clips that cannot play.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "audio_test_support.h"
#include "candela/content/audio_clip.h"

namespace candela::audio::test {
namespace {

using content::AudioSource;
using content::PlaybackState;

// The largest step between neighbouring samples: a click at a loop seam is a step far larger
// than the tone's own (a sine of peak A at f Hz steps at most 2 pi f A / rate).
float largestStep(const std::vector<float>& samples, std::size_t from = 0) {
    float largest = 0;
    for (std::size_t i = from + 1; i < samples.size(); ++i)
        largest = std::max(largest, std::abs(samples[i] - samples[i - 1]));
    return largest;
}

float peak(const std::vector<float>& samples, std::size_t from = 0) {
    float p = 0;
    for (std::size_t i = from; i < samples.size(); ++i)
        p = std::max(p, std::abs(samples[i]));
    return p;
}

TEST(Playback, ALoopedClipHasNoClickAtTheSeam) {
    // 0.1 s of 1 kHz at the device's rate and at 44.1 kHz (resampled): 100 whole periods, so
    // a seamless loop is a continuous sine through every seam.
    for (std::uint32_t rate : {kRate, 44100u}) {
        SCOPED_TRACE(rate);
        LoopbackMix mix;
        mix.addListener({0, 0, 0});
        AudioSource source;
        source.clip =
            writeClip("seam" + std::to_string(rate) + ".wav", sine(0.1, 1000.0, 0.5f, rate), rate)
                .string();
        source.loop = true;
        source.spatial = false;
        mix.addSource(source, {});
        const Channels c = mix.run(30);  // 1 s: ten seams
        const float amplitude = peak(c.left);
        ASSERT_GT(amplitude, 0.1f);
        const float sineStep = float(2 * std::numbers::pi * 1000.0 / kRate) * amplitude;
        EXPECT_LT(largestStep(c.left), 1.02f * sineStep);
        // Still playing at the end: looping never stops.
        EXPECT_GT(rms(c.left, c.left.size() - 1600), 0.9 * amplitude / std::sqrt(2.0));
    }
}

TEST(Playback, AOneShotEndsStopsItsComponentAndPlaysAgainOnPlay) {
    LoopbackMix mix;
    mix.addListener({0, 0, 0});
    AudioSource source;
    source.clip = writeClip("shot.wav", sine(0.05, 1000.0, 0.5f, kRate)).string();
    const ecs::Entity e = mix.addSource(source, {0, 0, -1});
    Channels c = mix.run(3);
    EXPECT_GT(rms(std::vector<float>(c.left.begin(), c.left.begin() + 2400)), 0.1);
    EXPECT_EQ(peak(c.left, 2400), 0.0f);  // after its 2,400 frames, silence
    mix.run(1);                           // the update after it ended sees it stopped
    EXPECT_EQ(mix.registry.get<AudioSource>(e).state, PlaybackState::Stopped);
    EXPECT_EQ(mix.system->counts().playing, 0u);
    mix.registry.patch<AudioSource>(e, [](AudioSource& a) { a.play(); });
    c = mix.run(1);
    EXPECT_GT(rms(c.left), 0.1);
}

TEST(Playback, PlayRestartsAClipThatIsStillPlaying) {
    LoopbackMix mix;
    mix.addListener({0, 0, 0});
    AudioSource source;
    source.clip = writeClip("long_shot.wav", sine(0.1, 1000.0, 0.5f, kRate)).string();
    const ecs::Entity e = mix.addSource(source, {0, 0, -1});
    mix.run(2);  // 3,200 of its 4,800 frames
    mix.registry.patch<AudioSource>(e, [](AudioSource& a) { a.play(); });
    const Channels c = mix.run(4);
    // From the start again: it sounds for 4,800 more frames, not the 1,600 it had left.
    EXPECT_GT(rms(std::vector<float>(c.left.begin() + 3000, c.left.begin() + 4700)), 0.1);
    EXPECT_EQ(peak(c.left, 4800), 0.0f);
}

TEST(Playback, PausedIsSilentAndResumesWhereItStopped) {
    LoopbackMix mix;
    mix.addListener({0, 0, 0});
    AudioSource source;
    source.clip = writeClip("pause.wav", sine(0.1, 1000.0, 0.5f, kRate)).string();
    const ecs::Entity e = mix.addSource(source, {0, 0, -1});
    mix.run(1);
    mix.registry.patch<AudioSource>(e, [](AudioSource& a) { a.pause(); });
    EXPECT_EQ(peak(mix.run(3).left), 0.0f);
    mix.registry.patch<AudioSource>(e, [](AudioSource& a) { a.resume(); });
    const Channels c = mix.run(3);
    // The 3,200 frames it had left, then silence.
    EXPECT_GT(rms(std::vector<float>(c.left.begin(), c.left.begin() + 3100)), 0.1);
    EXPECT_EQ(peak(c.left, 3200), 0.0f);
    mix.registry.patch<AudioSource>(e, [](AudioSource& a) { a.stop(); });
    EXPECT_EQ(peak(mix.run(1).left), 0.0f);
}

TEST(Playback, AStreamedClipPlaysItsSamplesAndLoopsWithoutASeam) {
    content::Diagnostics diagnostics;
    const auto clip = content::loadAudioClip(testSound("music_12s.ogg"), diagnostics);
    ASSERT_TRUE(clip && clip->streamed()) << diagnostics.toString();
    std::vector<float> decoded(2 * clip->frames);
    content::AudioClipStream stream(clip);
    ASSERT_EQ(stream.read(decoded), clip->frames);

    LoopbackMix mix;
    mix.addListener({0, 0, 0});
    AudioSource source;
    source.clip = testSound("music_12s.ogg").string();
    source.loop = true;
    source.spatial = false;
    mix.addSource(source, {});
    const Channels c = mix.run(30 * 26);  // 26 s: past two seams
    EXPECT_EQ(mix.system->counts().streamed, 1u);
    // A stereo clip plays as recorded: each output sample is the clip's, wrapped at its end.
    float worst = 0;
    for (std::size_t i = 0; i < c.left.size(); ++i) {
        const std::size_t at = i % clip->frames;
        worst = std::max({worst, std::abs(c.left[i] - decoded[2 * at]),
                          std::abs(c.right[i] - decoded[2 * at + 1])});
    }
    EXPECT_LT(worst, 1e-6f);
}

TEST(Playback, TheSameMixGivesTheSameSamples) {
    const auto once = [] {
        LoopbackMix mix;
        const ecs::Entity listener = mix.addListener({0, 0, 0});
        AudioSource source;
        source.clip = writeClip("same.wav", sine(0.1, 440.0, 0.5f, kRate)).string();
        source.loop = true;
        const ecs::Entity e = mix.addSource(source, {-3, 0, -1});
        Channels all;
        for (int step = 0; step < 20; ++step) {
            mix.move(e, {-3 + 0.3f * float(step), 0, -1});
            mix.move(listener, {0, 0, 0.1f * float(step)});
            const Channels c = mix.run(1);
            all.left.insert(all.left.end(), c.left.begin(), c.left.end());
            all.right.insert(all.right.end(), c.right.begin(), c.right.end());
        }
        return all;
    };
    const Channels a = once(), b = once();
    EXPECT_EQ(a.left, b.left);
    EXPECT_EQ(a.right, b.right);
}

TEST(Playback, ClipsThatCannotPlayAreReportedOnceAndTheRestPlays) {
    LoopbackMix mix;
    mix.addListener({0, 0, 0});
    const auto bad = [&](const std::string& name, std::vector<float> samples, std::size_t cut) {
        const std::filesystem::path path = writeClip(name, samples);
        std::filesystem::resize_file(path, std::filesystem::file_size(path) - cut);
        return path.string();
    };
    AudioSource missing, truncated, notAudio, good;
    missing.clip = "/nonexistent/sounds/missing.wav";
    truncated.clip = bad("truncated.wav", sine(0.1, 1000.0, 0.5f, kRate), 100);
    notAudio.clip = std::string(CANDELA_TEST_SOUNDS) + "/../CMakeLists.txt";
    good.clip = writeClip("good.wav", sine(0.1, 1000.0, 0.5f, kRate)).string();
    good.loop = true;
    for (const AudioSource& s : {missing, truncated, notAudio, good})
        mix.addSource(s, {0, 0, -1});
    const Channels c = mix.run(10);
    EXPECT_GT(rms(c.left, 1600), 0.1);  // the good one plays
    EXPECT_EQ(mix.system->counts().voices, 1u);
    EXPECT_EQ(mix.diagnostics.count(content::Severity::Error), 3u) << mix.diagnostics.toString();
    EXPECT_TRUE(mix.diagnostics.mentions("no such file"));
    EXPECT_TRUE(mix.diagnostics.mentions("truncated"));
    EXPECT_TRUE(mix.diagnostics.mentions("not an audio clip"));
    // Each names its file.
    for (const content::Diagnostic& d : mix.diagnostics.messages) {
        const std::string name = std::filesystem::path(d.file).filename().string();
        EXPECT_TRUE(name == "missing.wav" || name == "truncated.wav" || name == "CMakeLists.txt")
            << d.file;
    }
    mix.run(3);
    EXPECT_EQ(mix.diagnostics.messages.size(), 3u);  // once, not every frame
}

}  // namespace
}  // namespace candela::audio::test
