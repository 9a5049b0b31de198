// candela-bench-audio: what the mix costs and how true it is.
//   --speed-vs-error   markdown tables for docs/audio-speed-vs-error.md (scripts/audio-report)
//   --voices N --seconds S   one timing: N looping spatial voices mixed for S seconds
//
// Resamplers: a 44.1 kHz sine played on the 48 kHz loopback device through each of OpenAL
// Soft's resamplers (AL_SOFT_source_resampler), its error against the ideal sine at the
// frequency the mixer actually plays (its 12-bit fixed-point step moves 44.1 kHz material by
// -53 ppm; the phase and amplitude are fitted by least squares), and the cost of mixing 64
// such voices. Voices: the engine's path (AudioSystem::update and the loopback render) per
// 1/30 s frame. Streaming: decoding Ogg Vorbis as it plays against decoding it whole.
#define AL_ALEXT_PROTOTYPES  // alGetStringiSOFT
#include <AL/al.h>
#include <AL/alext.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <string>
#include <vector>

#include "audio_test_support.h"
#include "candela/content/audio_clip.h"

using namespace candela;
using namespace candela::audio;

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

// Residual of `y` after the best-fitting a sin + b cos at `frequency` (cycles per sample),
// relative to the fitted sine's RMS, in dB (lower is truer).
double errorDb(const std::vector<float>& y, double frequency) {
    double ss = 0, cc = 0, sc = 0, ys = 0, yc = 0;
    for (std::size_t n = 0; n < y.size(); ++n) {
        const double s = std::sin(2 * std::numbers::pi * frequency * double(n));
        const double c = std::cos(2 * std::numbers::pi * frequency * double(n));
        ss += s * s, cc += c * c, sc += s * c, ys += y[n] * s, yc += y[n] * c;
    }
    const double det = ss * cc - sc * sc;
    const double a = (ys * cc - yc * sc) / det, b = (yc * ss - ys * sc) / det;
    double residual = 0, signal = 0;
    for (std::size_t n = 0; n < y.size(); ++n) {
        const double fit = a * std::sin(2 * std::numbers::pi * frequency * double(n)) +
                           b * std::cos(2 * std::numbers::pi * frequency * double(n));
        residual += (y[n] - fit) * (y[n] - fit);
        signal += fit * fit;
    }
    return 10.0 * std::log10(std::max(residual, 1e-30) / signal);
}

// Mixes `voices` copies of a 44.1 kHz sine at `hz` through resampler `index`; returns the left
// channel of the first 0.5 s after a 0.1 s settle, and the seconds the mixing took.
std::pair<std::vector<float>, double> resample(int index, double hz, int voices) {
    test::LoopbackMix mix;
    const std::vector<float> clip = test::sine(1.0, hz, 0.5f / float(voices), 44100);
    content::AudioSource source;
    source.clip =
        test::writeClip("resample_" + std::to_string(int(hz)) + ".wav", clip, 44100).string();
    source.loop = true;
    source.spatial = false;
    for (int v = 0; v < voices; ++v)
        mix.addSource(source, {});
    mix.system->update(mix.registry, mix.cache, 0.0, mix.diagnostics);
    // The engine leaves OpenAL's default; the bench sets each source's resampler directly.
    ALint count = 0;
    std::vector<ALuint> sources(64);
    for (ALuint id = 1; id < 4096 && count < voices; ++id) {
        if (alIsSource(id)) sources[std::size_t(count++)] = id;
    }
    for (int v = 0; v < count; ++v)
        alSourcei(sources[std::size_t(v)], AL_SOURCE_RESAMPLER_SOFT, index);
    std::vector<float> buffer(2 * 1600), left;
    const auto start = Clock::now();
    for (int frame = 0; frame < 30; ++frame) {
        mix.device->render(buffer);
        for (std::size_t f = 0; f < 1600; ++f)
            left.push_back(buffer[2 * f]);
    }
    const double seconds = secondsSince(start);
    return {std::vector<float>(left.begin() + 4800, left.begin() + 4800 + 24000), seconds};
}

void resamplerTable() {
    std::vector<std::string> names;
    ALint fallback = 0;
    {
        test::LoopbackMix probe;  // a current context, to ask OpenAL for its resamplers
        fallback = alGetInteger(AL_DEFAULT_RESAMPLER_SOFT);
        for (ALint i = 0; i < alGetInteger(AL_NUM_RESAMPLERS_SOFT); ++i)
            names.push_back(alGetStringiSOFT(AL_RESAMPLER_NAME_SOFT, i));
    }
    const auto count = static_cast<ALint>(names.size());
    // The mixer's step for 44.1 kHz at 48 kHz, in its 12 fractional bits.
    const double step = std::round(44100.0 / 48000.0 * 4096.0) / 4096.0;
    std::printf("| resampler | error at 1 kHz | error at 10 kHz | ms to mix 1 s of 64 voices |\n");
    std::printf("|---|---:|---:|---:|\n");
    for (ALint i = 0; i < count; ++i) {
        double e1 = 0, e10 = 0;
        for (double hz : {1000.0, 10000.0}) {
            const auto [left, seconds] = resample(i, hz, 1);
            (hz == 1000.0 ? e1 : e10) = errorDb(left, hz / 44100.0 * step);
        }
        std::vector<double> costs;
        for (int round = 0; round < 3; ++round)
            costs.push_back(resample(i, 1000.0, 64).second * 1e3);
        std::printf("| %s%s | %.1f dB | %.1f dB | %.2f |\n", names[std::size_t(i)].c_str(),
                    i == fallback ? " (OpenAL's default, the engine's)" : "", e1, e10,
                    median(costs));
    }
}

double mixMillisecondsPerFrame(int voices, int frames) {
    test::LoopbackMix mix;
    mix.addListener({0, 0, 0});
    content::AudioSource source;
    source.clip = test::writeClip("voice.wav", test::sine(0.5, 440.0, 0.01f, 48000)).string();
    source.loop = true;
    for (int v = 0; v < voices; ++v) {
        const float a = float(v) * 0.7f;
        mix.addSource(source, {5 * std::cos(a), 0, 5 * std::sin(a)});
    }
    mix.run(2);
    std::vector<double> times;
    std::vector<float> buffer(2 * 1600);
    for (int f = 0; f < frames; ++f) {
        const auto start = Clock::now();
        mix.system->update(mix.registry, mix.cache, 1.0 / 30.0, mix.diagnostics);
        mix.device->render(buffer);
        times.push_back(secondsSince(start) * 1e3);
    }
    return median(times);
}

void voiceTable(int frames) {
    std::printf("| voices | ms per 1/30 s frame (sync + mix) | share of a 33 ms frame |\n");
    std::printf("|---:|---:|---:|\n");
    for (int voices : {1, 16, 64, 256}) {
        const double ms = mixMillisecondsPerFrame(voices, frames);
        std::printf("| %d | %.3f | %.2f%% |\n", voices, ms, 100.0 * ms / (1000.0 / 30.0));
    }
}

void streamingTable() {
    content::Diagnostics diagnostics;
    const auto clip = content::loadAudioClip(test::testSound("music_12s.ogg"), diagnostics);
    if (!clip) {
        std::printf("%s\n", diagnostics.toString().c_str());
        return;
    }
    std::vector<float> chunk(2 * 8192);
    std::vector<double> times;
    for (int round = 0; round < 3; ++round) {
        content::AudioClipStream stream(clip);
        const auto start = Clock::now();
        while (stream.read(chunk) > 0) {
        }
        times.push_back(secondsSince(start) * 1e3);
    }
    const double ms = median(times);
    const double decodedBytes = double(clip->frames) * clip->channels * sizeof(float);
    std::printf("| Ogg Vorbis, %.0f s stereo | held in memory | decoding cost |\n",
                clip->seconds());
    std::printf("|---|---:|---:|\n");
    std::printf("| decoded whole | %.1f MB | once, %.0f ms at load |\n", decodedBytes / 1e6, ms);
    std::printf(
        "| streamed (the engine, above %.0f s) | %.2f MB | %.2f ms per second played "
        "(%.3f%% of a core) |\n",
        content::kStreamAboveSeconds, double(clip->encoded.size()) / 1e6, ms / clip->seconds(),
        100.0 * ms / clip->seconds() / 1000.0);
}

}  // namespace

int main(int argc, char** argv) {
    int voices = 0;
    double seconds = 1.0;
    bool table = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--speed-vs-error") {
            table = true;
        } else if (arg == "--voices" && i + 1 < argc) {
            voices = std::atoi(argv[++i]);
        } else if (arg == "--seconds" && i + 1 < argc) {
            seconds = std::atof(argv[++i]);
        } else {
            std::fprintf(
                stderr, "usage: candela-bench-audio --speed-vs-error | --voices N [--seconds S]\n");
            return 2;
        }
    }
    try {
        if (table) {
            std::printf("### Resamplers (a 44.1 kHz clip on the 48 kHz mix)\n\n");
            resamplerTable();
            std::printf("\n### Voices\n\n");
            voiceTable(90);
            std::printf("\n### Streaming\n\n");
            streamingTable();
            return 0;
        }
        const int frames = std::max(1, int(seconds * 30.0));
        std::printf("%d voices: %.3f ms per frame (median of %d)\n", std::max(voices, 1),
                    mixMillisecondsPerFrame(std::max(voices, 1), frames), frames);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "candela-bench-audio: %s\n", e.what());
        return 1;
    }
    return 0;
}
