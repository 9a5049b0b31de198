// Ogg Vorbis through stb_vorbis: short clips decoded whole, long ones kept encoded and
// streamed (AudioClipStream).
#include <cstdint>
#include <limits>

#include "vorbis_file.h"
#include "wav_decoding.h"

namespace candela::content {

std::string decodeVorbis(std::span<const std::byte> bytes, AudioClip& clip) {
    if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        return "Ogg Vorbis file is too large";
    int error = 0;
    stb_vorbis* vorbis =
        stb_vorbis_open_memory(reinterpret_cast<const unsigned char*>(bytes.data()),
                               static_cast<int>(bytes.size()), &error, nullptr);
    if (!vorbis)
        return "not a readable Ogg Vorbis stream (stb_vorbis error " + std::to_string(error) + ")";
    const stb_vorbis_info info = stb_vorbis_get_info(vorbis);
    const std::uint64_t length = stb_vorbis_stream_length_in_samples(vorbis);
    std::string problem;
    if (info.channels != 1 && info.channels != 2)
        problem =
            "Ogg Vorbis has " + std::to_string(info.channels) + " channels (mono or stereo only)";
    else if (info.sample_rate < 8000 || info.sample_rate > 192000)
        problem = "Ogg Vorbis sample rate " + std::to_string(info.sample_rate) +
                  " Hz is outside 8,000..192,000";
    else if (length == 0)
        problem = "Ogg Vorbis holds no samples (or its last page is missing: truncated)";
    if (!problem.empty()) {
        stb_vorbis_close(vorbis);
        return problem;
    }
    clip.sampleRate = info.sample_rate;
    clip.channels = static_cast<std::uint32_t>(info.channels);
    clip.frames = length;
    if (clip.seconds() > kStreamAboveSeconds) {
        clip.encoded.assign(bytes.begin(), bytes.end());
        stb_vorbis_close(vorbis);
        return {};
    }
    clip.samples.resize(length * clip.channels);
    std::uint64_t decoded = 0;
    while (decoded < length) {
        const int want =
            static_cast<int>(std::min<std::uint64_t>(length - decoded, 4096) * clip.channels);
        const int got = stb_vorbis_get_samples_float_interleaved(
            vorbis, info.channels, clip.samples.data() + decoded * clip.channels, want);
        if (got <= 0) break;
        decoded += static_cast<std::uint64_t>(got);
    }
    stb_vorbis_close(vorbis);
    if (decoded < length)
        return "Ogg Vorbis is truncated or corrupt: decoded " + std::to_string(decoded) + " of " +
               std::to_string(length) + " frames";
    return {};
}

}  // namespace candela::content
