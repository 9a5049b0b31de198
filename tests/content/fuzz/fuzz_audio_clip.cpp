// libFuzzer target: any bytes as an audio clip (WAV or Ogg Vorbis, told apart by their first
// bytes), decoded and, when it decodes, read to its end through a stream and again after a
// rewind, the way a playing voice reads it.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "candela/content/audio_clip.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    candela::content::Diagnostics diagnostics;
    const auto clip = candela::content::decodeAudioClip(
        {reinterpret_cast<const std::byte*>(data), size}, "fuzz.wav", diagnostics);
    if (!clip) return 0;
    candela::content::AudioClipStream stream(clip);
    std::vector<float> chunk(2 * 4096);
    for (int pass = 0; pass < 2; ++pass) {
        std::uint64_t frames = 0;
        for (std::size_t got; (got = stream.read(chunk)) > 0 && frames < (1u << 22);)
            frames += got;
        stream.rewind();
    }
    return 0;
}
