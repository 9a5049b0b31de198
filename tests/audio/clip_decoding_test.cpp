// WAV and Ogg Vorbis clips: every WAV sample format decodes to the same values, Ogg Vorbis to
// its tone, long Ogg files stream, and bad files are errors that name the file.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "audio_test_support.h"
#include "candela/content/audio_clip.h"

namespace candela::audio::test {
namespace {

using content::AudioClip;
using content::Diagnostics;

void put(std::vector<std::byte>& out, std::uint32_t value, int bytes) {
    for (int i = 0; i < bytes; ++i)
        out.push_back(std::byte((value >> (8 * i)) & 0xFF));
}
void tag(std::vector<std::byte>& out, const char* text) {
    for (int i = 0; i < 4; ++i)
        out.push_back(std::byte(text[i]));
}

// A WAV of `values` in the given format; `extensible` wraps the tag in WAVE_FORMAT_EXTENSIBLE;
// `junk` puts an odd-sized chunk before "data" (padded, as RIFF requires).
std::vector<std::byte> wav(const std::vector<float>& values, std::uint16_t formatTag,
                           std::uint16_t bits, std::uint16_t channels = 1, bool extensible = false,
                           bool junk = false) {
    std::vector<std::byte> data;
    for (float v : values) {
        if (formatTag == 3 && bits == 32) {
            std::uint32_t u;
            std::memcpy(&u, &v, 4);
            put(data, u, 4);
        } else if (bits == 8) {
            put(data, std::uint32_t(std::lround(v * 127.0f) + 128), 1);
        } else {
            const double scale = std::ldexp(1.0, bits - 1) - 1;
            put(data, std::uint32_t(std::int32_t(std::lround(v * scale))), bits / 8);
        }
    }
    std::vector<std::byte> out;
    tag(out, "RIFF");
    put(out, 0, 4);  // RIFF size: readers do not need it
    tag(out, "WAVE");
    tag(out, "fmt ");
    put(out, extensible ? 40 : 16, 4);
    put(out, extensible ? 0xFFFE : formatTag, 2);
    put(out, channels, 2);
    put(out, 48000, 4);
    put(out, 48000u * channels * bits / 8, 4);
    put(out, channels * bits / 8, 2);
    put(out, bits, 2);
    if (extensible) {
        put(out, 22, 2);    // cbSize
        put(out, bits, 2);  // valid bits
        put(out, 0, 4);     // channel mask
        put(out, formatTag, 2);
        for (int i = 0; i < 14; ++i)
            out.push_back(std::byte{0});  // the rest of the sub-format GUID
    }
    if (junk) {
        tag(out, "LIST");
        put(out, 3, 4);
        for (int i = 0; i < 4; ++i)
            out.push_back(std::byte{'x'});  // 3 bytes and the pad byte
    }
    tag(out, "data");
    put(out, std::uint32_t(data.size()), 4);
    out.insert(out.end(), data.begin(), data.end());
    return out;
}

std::shared_ptr<const AudioClip> decode(const std::vector<std::byte>& bytes,
                                        Diagnostics& diagnostics) {
    return content::decodeAudioClip(bytes, "clip.wav", diagnostics);
}

const std::vector<float> kRamp = {0.0f, 0.5f, -0.5f, 0.25f, -1.0f, 0.99f};

TEST(ClipDecoding, EveryWavSampleFormatDecodesToTheSameValues) {
    struct Case {
        std::uint16_t formatTag, bits;
        bool extensible;
        float tolerance;  // one quantisation step
    };
    for (const Case c :
         {Case{1, 8, false, 1.0f / 64}, Case{1, 16, false, 1.0f / 16384}, Case{1, 24, false, 1e-6f},
          Case{1, 32, false, 1e-6f}, Case{3, 32, false, 0.0f}, Case{1, 16, true, 1.0f / 16384},
          Case{3, 32, true, 0.0f}}) {
        SCOPED_TRACE(std::to_string(c.formatTag) + "/" + std::to_string(c.bits) +
                     (c.extensible ? " extensible" : ""));
        Diagnostics diagnostics;
        const auto clip = decode(wav(kRamp, c.formatTag, c.bits, 1, c.extensible), diagnostics);
        ASSERT_TRUE(clip) << diagnostics.toString();
        EXPECT_EQ(clip->sampleRate, 48000u);
        EXPECT_EQ(clip->channels, 1u);
        ASSERT_EQ(clip->frames, kRamp.size());
        for (std::size_t i = 0; i < kRamp.size(); ++i)
            EXPECT_NEAR(clip->samples[i], kRamp[i], c.tolerance) << "sample " << i;
    }
}

TEST(ClipDecoding, OddSizedChunksBeforeTheDataAreSkipped) {
    Diagnostics diagnostics;
    const auto clip = decode(wav(kRamp, 1, 16, 1, false, true), diagnostics);
    ASSERT_TRUE(clip) << diagnostics.toString();
    EXPECT_EQ(clip->frames, kRamp.size());
    EXPECT_NEAR(clip->samples[1], 0.5f, 1e-4f);
}

TEST(ClipDecoding, BadWavFilesAreErrorsNamingTheFileAndTheProblem) {
    struct Case {
        std::vector<std::byte> bytes;
        const char* problem;
    };
    std::vector<std::byte> truncated = wav(kRamp, 1, 16);
    truncated.resize(truncated.size() - 5);
    std::vector<std::byte> noData = wav({}, 1, 16);
    noData.resize(noData.size() - 8);
    const std::vector<std::byte> png = {std::byte{0x89}, std::byte{'P'}, std::byte{'N'},
                                        std::byte{'G'},  std::byte{0},   std::byte{0}};
    for (const Case& c : {Case{truncated, "truncated"}, Case{wav(kRamp, 1, 16, 3), "channels"},
                          Case{wav(kRamp, 1, 12), "12-bit"}, Case{noData, "no \"data\""},
                          Case{png, "not an audio clip"}, Case{{}, "not an audio clip"}}) {
        SCOPED_TRACE(c.problem);
        Diagnostics diagnostics;
        EXPECT_FALSE(decode(c.bytes, diagnostics));
        ASSERT_EQ(diagnostics.messages.size(), 1u);
        EXPECT_EQ(diagnostics.messages[0].file, "clip.wav");
        EXPECT_TRUE(diagnostics.mentions(c.problem)) << diagnostics.toString();
        EXPECT_TRUE(diagnostics.mentions("silence")) << diagnostics.toString();
    }
}

TEST(ClipDecoding, AMissingFileIsAnErrorNamingIt) {
    Diagnostics diagnostics;
    EXPECT_FALSE(content::loadAudioClip("/nonexistent/sounds/gone.wav", diagnostics));
    EXPECT_TRUE(diagnostics.mentions("no such file")) << diagnostics.toString();
    EXPECT_EQ(diagnostics.messages.at(0).file, "/nonexistent/sounds/gone.wav");
}

TEST(ClipDecoding, OggVorbisDecodesItsToneWhole) {
    Diagnostics diagnostics;
    const auto clip = content::loadAudioClip(testSound("tone_1khz.ogg"), diagnostics);
    ASSERT_TRUE(clip) << diagnostics.toString();
    EXPECT_FALSE(clip->streamed());
    EXPECT_EQ(clip->sampleRate, 48000u);
    EXPECT_EQ(clip->channels, 1u);
    EXPECT_EQ(clip->frames, 48000u);
    // A 0.5 peak sine: RMS 0.5 / sqrt(2), within what the lossy codec changes.
    EXPECT_NEAR(rms(clip->samples), 0.5 / std::sqrt(2.0), 0.01);
    // Ten periods per 480 samples: the crossings of a 1 kHz tone.
    int crossings = 0;
    for (std::size_t i = 1; i < clip->samples.size(); ++i)
        crossings += (clip->samples[i - 1] < 0) != (clip->samples[i] < 0);
    EXPECT_NEAR(crossings, 2000, 4);
}

TEST(ClipDecoding, ALongOggVorbisFileStreamsTheSameSamplesAfterARewind) {
    Diagnostics diagnostics;
    const auto clip = content::loadAudioClip(testSound("music_12s.ogg"), diagnostics);
    ASSERT_TRUE(clip) << diagnostics.toString();
    ASSERT_TRUE(clip->streamed());
    EXPECT_TRUE(clip->samples.empty());
    EXPECT_EQ(clip->channels, 2u);
    EXPECT_EQ(clip->frames, 12u * 48000u);
    content::AudioClipStream stream(clip);
    std::vector<float> first, chunk(2 * 5000);
    for (std::size_t got; (got = stream.read(chunk)) > 0;)
        first.insert(first.end(), chunk.begin(), chunk.begin() + std::ptrdiff_t(2 * got));
    EXPECT_EQ(first.size(), 2 * clip->frames);
    EXPECT_NEAR(rms(first), 0.3 / std::sqrt(2.0), 0.01);
    stream.rewind();
    std::vector<float> again(2 * 1000);
    ASSERT_EQ(stream.read(again), 1000u);
    EXPECT_TRUE(std::equal(again.begin(), again.end(), first.begin()));
}

TEST(ClipDecoding, AGarbledOggFileIsAnError) {
    std::vector<std::byte> bytes(4096, std::byte{0x5A});
    std::memcpy(bytes.data(), "OggS", 4);
    Diagnostics diagnostics;
    EXPECT_FALSE(content::decodeAudioClip(bytes, "garbled.ogg", diagnostics));
    EXPECT_TRUE(diagnostics.mentions("Ogg Vorbis")) << diagnostics.toString();
}

TEST(ClipDecoding, TheAssetCacheLoadsAClipOnceAndRemembersAFailure) {
    content::AssetCache cache;
    Diagnostics diagnostics;
    const auto a = cache.audioClip(testSound("tone_1khz.ogg"), diagnostics);
    const auto b = cache.audioClip(testSound("../sounds/tone_1khz.ogg"), diagnostics);
    EXPECT_TRUE(a);
    EXPECT_EQ(a, b);
    EXPECT_FALSE(cache.audioClip("/nonexistent.wav", diagnostics));
    EXPECT_FALSE(cache.audioClip("/nonexistent.wav", diagnostics));
    EXPECT_EQ(diagnostics.messages.size(), 1u) << diagnostics.toString();
    EXPECT_EQ(cache.stats().audioClipLoads, 2u);
}

}  // namespace
}  // namespace candela::audio::test
