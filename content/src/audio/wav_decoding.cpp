// RIFF WAVE: a "fmt " chunk (PCM, IEEE float, or WAVE_FORMAT_EXTENSIBLE holding either) and a
// "data" chunk; other chunks are skipped. Every size is checked against the file before use.
#include "clip_decoding.h"

#include <cstdint>
#include <cstring>
#include <optional>

namespace candela::content {
namespace {

constexpr std::uint16_t kFormatPcm = 1;
constexpr std::uint16_t kFormatFloat = 3;
constexpr std::uint16_t kFormatExtensible = 0xFFFE;

std::uint32_t u32(const std::byte* p) {
    return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 |
           std::uint32_t(p[3]) << 24;
}
std::uint16_t u16(const std::byte* p) {
    return static_cast<std::uint16_t>(std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8);
}
bool tagIs(const std::byte* p, const char* tag) {
    return std::memcmp(p, tag, 4) == 0;
}

struct Format {
    std::uint16_t tag = 0;
    std::uint16_t channels = 0;
    std::uint32_t sampleRate = 0;
    std::uint16_t bitsPerSample = 0;
    std::uint16_t blockAlign = 0;
};

// One sample to -1..1. Integer PCM is scaled by 2^(bits-1), so full scale reads as exactly 1.
float sampleAt(const std::byte* p, const Format& format) {
    switch (format.bitsPerSample) {
        case 8:
            return (static_cast<float>(std::uint8_t(p[0])) - 128.0f) / 128.0f;
        case 16:
            return static_cast<float>(static_cast<std::int16_t>(u16(p))) / 32768.0f;
        case 24: {
            // The three bytes as the top of a 32-bit word, shifted back down with the sign.
            const std::int32_t v =
                static_cast<std::int32_t>(std::uint32_t(p[0]) << 8 | std::uint32_t(p[1]) << 16 |
                                          std::uint32_t(p[2]) << 24) >>
                8;
            return static_cast<float>(v) / 8388608.0f;
        }
        case 32:
            if (format.tag == kFormatFloat) {
                float f;
                const std::uint32_t bits = u32(p);
                std::memcpy(&f, &bits, 4);
                return f;
            }
            return static_cast<float>(static_cast<double>(static_cast<std::int32_t>(u32(p))) /
                                      2147483648.0);
        case 64: {
            double d;
            const std::uint64_t bits = std::uint64_t(u32(p)) | std::uint64_t(u32(p + 4)) << 32;
            std::memcpy(&d, &bits, 8);
            return static_cast<float>(d);
        }
    }
    return 0.0f;
}

std::string checkFormat(const Format& f) {
    if (f.tag != kFormatPcm && f.tag != kFormatFloat)
        return "WAV sample format " + std::to_string(f.tag) +
               " is not supported (PCM or IEEE float only)";
    if (f.channels != 1 && f.channels != 2)
        return "WAV has " + std::to_string(f.channels) + " channels (mono or stereo only)";
    if (f.sampleRate < 8000 || f.sampleRate > 192000)
        return "WAV sample rate " + std::to_string(f.sampleRate) + " Hz is outside 8,000..192,000";
    const bool pcmBits = f.bitsPerSample == 8 || f.bitsPerSample == 16 || f.bitsPerSample == 24 ||
                         f.bitsPerSample == 32;
    const bool floatBits = f.bitsPerSample == 32 || f.bitsPerSample == 64;
    if ((f.tag == kFormatPcm && !pcmBits) || (f.tag == kFormatFloat && !floatBits))
        return "WAV has " + std::to_string(f.bitsPerSample) + "-bit " +
               (f.tag == kFormatPcm ? "PCM" : "float") + " samples (unsupported)";
    if (f.blockAlign != f.channels * (f.bitsPerSample / 8))
        return "WAV block alignment " + std::to_string(f.blockAlign) + " does not match " +
               std::to_string(f.channels) + " channels of " + std::to_string(f.bitsPerSample) +
               " bits";
    return {};
}

}  // namespace

std::string decodeWav(std::span<const std::byte> bytes, AudioClip& clip) {
    if (bytes.size() < 12 || !tagIs(bytes.data(), "RIFF") || !tagIs(bytes.data() + 8, "WAVE"))
        return "not a WAV file (no RIFF WAVE header)";
    std::optional<Format> format;
    std::span<const std::byte> data;
    bool haveData = false;
    std::size_t at = 12;
    while (at + 8 <= bytes.size()) {
        const std::byte* chunk = bytes.data() + at;
        const std::uint64_t size = u32(chunk + 4);
        const std::uint64_t available = bytes.size() - at - 8;
        if (tagIs(chunk, "fmt ")) {
            if (size < 16 || size > available) return "WAV \"fmt \" chunk is truncated";
            Format f;
            f.tag = u16(chunk + 8);
            f.channels = u16(chunk + 10);
            f.sampleRate = u32(chunk + 12);
            f.blockAlign = u16(chunk + 20);
            f.bitsPerSample = u16(chunk + 22);
            // WAVE_FORMAT_EXTENSIBLE: the real tag is the sub-format GUID's first two bytes.
            if (f.tag == kFormatExtensible) {
                if (size < 40) return "WAV extensible \"fmt \" chunk is truncated";
                f.tag = u16(chunk + 8 + 24);
            }
            format = f;
        } else if (tagIs(chunk, "data")) {
            if (!format) return "WAV \"data\" chunk comes before its \"fmt \" chunk";
            if (size > available)
                return "WAV is truncated: its \"data\" chunk claims " + std::to_string(size) +
                       " bytes, the file holds " + std::to_string(available);
            data = bytes.subspan(at + 8, static_cast<std::size_t>(size));
            haveData = true;
            break;
        }
        if (size > available) return "WAV chunk at byte " + std::to_string(at) + " is truncated";
        at += 8 + static_cast<std::size_t>(size) + (size & 1);  // chunks are padded to even sizes
    }
    if (!format) return "WAV has no \"fmt \" chunk";
    if (!haveData) return "WAV has no \"data\" chunk";
    if (std::string problem = checkFormat(*format); !problem.empty()) return problem;
    const std::size_t frames = data.size() / format->blockAlign;
    if (frames == 0) return "WAV holds no samples";
    clip.sampleRate = format->sampleRate;
    clip.channels = format->channels;
    clip.frames = frames;
    clip.samples.resize(frames * format->channels);
    const std::size_t step = format->bitsPerSample / 8;
    for (std::size_t i = 0; i < clip.samples.size(); ++i)
        clip.samples[i] = sampleAt(data.data() + i * step, *format);
    return {};
}

}  // namespace candela::content
