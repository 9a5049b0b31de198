// Ogg Vorbis through libvorbisfile: short clips decoded whole, long ones kept encoded and
// streamed (AudioClipStream).
#include <cstdint>

#include "clip_decoding.h"
#include "vorbis_stream.h"

namespace candela::content {

std::string decodeVorbis(std::span<const std::byte> bytes, AudioClip& clip) {
    VorbisStream stream(bytes);
    if (!stream.ok()) return stream.error();
    const std::uint32_t channels = stream.channels(), rate = stream.sampleRate();
    const std::uint64_t length = stream.frames();
    if (channels != 1 && channels != 2)
        return "Ogg Vorbis has " + std::to_string(channels) + " channels (mono or stereo only)";
    if (rate < 8000 || rate > 192000)
        return "Ogg Vorbis sample rate " + std::to_string(rate) + " Hz is outside 8,000..192,000";
    if (length == 0) return "Ogg Vorbis holds no samples (or its last page is missing: truncated)";
    clip.sampleRate = rate;
    clip.channels = channels;
    clip.frames = length;
    if (clip.seconds() > kStreamAboveSeconds) {
        clip.encoded.assign(bytes.begin(), bytes.end());
        return {};
    }
    clip.samples.resize(length * channels);
    const std::size_t decoded = stream.read(clip.samples.data(), length);
    if (decoded < length)
        return "Ogg Vorbis is truncated or corrupt: decoded " + std::to_string(decoded) + " of " +
               std::to_string(length) + " frames";
    return {};
}

}  // namespace candela::content
