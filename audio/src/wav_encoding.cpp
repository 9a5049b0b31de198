#include "candela/audio/wav_encoding.h"

#include <algorithm>
#include <cmath>

namespace candela::audio {
namespace {

void put32(std::string& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i)
        out.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
}
void put16(std::string& out, std::uint32_t v) {
    out.push_back(static_cast<char>(v & 0xFF));
    out.push_back(static_cast<char>((v >> 8) & 0xFF));
}

}  // namespace

std::string encodeWav16(std::span<const float> samples, std::uint32_t sampleRate,
                        std::uint32_t channels) {
    const std::uint32_t dataBytes = static_cast<std::uint32_t>(samples.size() * 2);
    std::string out;
    out.reserve(44 + dataBytes);
    out += "RIFF";
    put32(out, 36 + dataBytes);
    out += "WAVEfmt ";
    put32(out, 16);
    put16(out, 1);  // PCM
    put16(out, channels);
    put32(out, sampleRate);
    put32(out, sampleRate * channels * 2);
    put16(out, channels * 2);
    put16(out, 16);
    out += "data";
    put32(out, dataBytes);
    for (float s : samples) {
        const float clipped = std::isnan(s) ? 0.0f : std::clamp(s, -1.0f, 1.0f);
        put16(out, static_cast<std::uint16_t>(
                       static_cast<std::int16_t>(std::lround(clipped * 32767.0f))));
    }
    return out;
}

}  // namespace candela::audio
