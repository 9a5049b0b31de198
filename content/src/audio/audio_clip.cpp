#include "candela/content/audio_clip.h"

#include <algorithm>
#include <cstring>

#include "candela/content/file_bytes.h"
#include "clip_decoding.h"
#include "vorbis_stream.h"

namespace candela::content {

std::shared_ptr<const AudioClip> decodeAudioClip(std::span<const std::byte> bytes,
                                                 const std::filesystem::path& path,
                                                 Diagnostics& diagnostics) {
    auto clip = std::make_shared<AudioClip>();
    std::string problem;
    if (bytes.size() >= 4 && std::memcmp(bytes.data(), "RIFF", 4) == 0)
        problem = decodeWav(bytes, *clip);
    else if (bytes.size() >= 4 && std::memcmp(bytes.data(), "OggS", 4) == 0)
        problem = decodeVorbis(bytes, *clip);
    else
        problem = "not an audio clip (neither a WAV nor an Ogg Vorbis file)";
    if (!problem.empty()) {
        diagnostics.error(path.string(), "", problem + "; it plays as silence");
        return nullptr;
    }
    return clip;
}

std::shared_ptr<const AudioClip> loadAudioClip(const std::filesystem::path& path,
                                               Diagnostics& diagnostics) {
    const FileBytes file = readFileBytes(path, kMaxAudioFileBytes);
    if (!file.error.empty()) {
        diagnostics.error(path.string(), "",
                          "cannot read audio clip: " + file.error + "; it plays as silence");
        return nullptr;
    }
    return decodeAudioClip(file.bytes, path, diagnostics);
}

struct AudioClipStream::Decoder {
    explicit Decoder(std::span<const std::byte> bytes) : stream(bytes) {}
    VorbisStream stream;
};

AudioClipStream::AudioClipStream(std::shared_ptr<const AudioClip> clip) : clip_(std::move(clip)) {
    if (!clip_->streamed()) return;
    decoder_ = std::make_unique<Decoder>(clip_->encoded);
}

AudioClipStream::~AudioClipStream() = default;

std::size_t AudioClipStream::read(std::span<float> out) {
    const std::size_t channels = clip_->channels;
    const std::size_t wanted = out.size() / channels;
    if (!decoder_) {
        const std::size_t frames = std::min<std::uint64_t>(wanted, clip_->frames - position_);
        std::copy_n(clip_->samples.begin() + static_cast<std::ptrdiff_t>(position_ * channels),
                    frames * channels, out.begin());
        position_ += frames;
        return frames;
    }
    // The stream opened when the clip was decoded; reading stops early only at damage.
    return decoder_->stream.read(out.data(), wanted);
}

void AudioClipStream::rewind() {
    position_ = 0;
    if (decoder_) decoder_->stream.rewind();
}

}  // namespace candela::content
