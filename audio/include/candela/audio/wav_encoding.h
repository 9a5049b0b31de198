#pragma once
// 16-bit PCM WAV bytes from float samples: what --audio-capture writes and tests compare.
#include <cstdint>
#include <span>
#include <string>

namespace candela::audio {

// `samples` interleaved, -1..1 (beyond is clipped); each rounds to the nearest of 65,535
// levels, so the same floats give the same bytes.
std::string encodeWav16(std::span<const float> samples, std::uint32_t sampleRate,
                        std::uint32_t channels);

}  // namespace candela::audio
